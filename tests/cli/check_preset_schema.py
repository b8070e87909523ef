#!/usr/bin/python3
"""Checks the JSON Schema `particle-lab schema` prints (Debian's python3-jsonschema):
every shipped preset is valid against it, and every file of the bad-preset catalogue is refused
by it, unless CANNOT_TELL below says why a schema cannot see that file's defect.

usage: check_preset_schema.py SCHEMA.json PRESETS_DIR BAD_PRESETS_DIR
"""
import json
import pathlib
import sys

import jsonschema

# Defects a JSON Schema cannot state (the loader refuses each of these files; bad_presets_test
# pins its message). Keyed by the catalogue file's name.
CANNOT_TELL = {
    "013_lone_surrogate_escape.json": "\\ud800 is well-formed JSON syntax to Python's parser; no schema keyword checks that a "
    "string is valid Unicode",
    "046_particle_outside_room.json": "a particle fits the room: a relation between particles[].position, radius and room",
    "047_particle_overlaps_floor.json": "a particle fits the room: a relation between particles[].position, radius and room",
    "048_particle_overlaps_corner.json": "a particle fits the room: a relation between particles[].position, radius and room",
    "049_radius_too_large.json": "radius < half the room's smallest size: a relation between two sections",
    "050_overlapping_walls.json": "radius < half the room's smallest size: a relation between two sections",
    "051_huge_integer_position.json": "a particle fits the room: a relation between particles[].position, radius and room",
    "080_duplicate_key.json": "duplicate keys: JSON parsers keep one of them before any schema sees the document",
    "085_too_many_particles_total.json": "listed + emitted <= 2000000: a sum over two sections",
    "087_emitter_speed_range_reversed.json": "speed_min <= speed_max: a relation between two fields",
    "088_emitter_region_reversed.json": "region_min <= region_max: a relation between two fields",
    "090_emitter_radius_too_large.json": "radius_max < half the room's smallest size: a relation between two sections",
    "094_duplicate_variant_label.json": "unique labels: uniqueItems compares whole variants, not one key of them",
    "110_expect_particle_out_of_range.json": "expect[].particle < the number of particles: a relation between two sections",
    "166_emitter_clump_with_collisions.json": "the emitter's volume fraction with collisions on: a product of count, radii, "
    "region and room, in any variant",
    "167_listed_clump_with_collisions.json": "the listed balls' overlapping pairs with collisions on: distances between "
    "every two particles, in any variant",
    "168_listed_crowd_beside_outliers_with_collisions.json": "the listed balls' overlapping pairs with collisions on: "
    "distances between every two particles, in any variant",
}


class NotJson(Exception):
    pass


def reject_constant(name):
    raise NotJson("not JSON: " + name)


def load(path):
    """The document, or NotJson: a file that is not JSON text (RFC 8259: UTF-8, no NaN) has no
    instance for a schema to accept."""
    data = path.read_bytes()
    try:
        text = data.decode("utf-8")
        return json.loads(text, parse_constant=reject_constant)
    except (UnicodeDecodeError, ValueError, RecursionError) as e:
        raise NotJson(str(e))


def main():
    schema_file, presets, catalogue = (pathlib.Path(a) for a in sys.argv[1:4])
    schema = json.loads(schema_file.read_text())
    jsonschema.Draft202012Validator.check_schema(schema)
    validator = jsonschema.Draft202012Validator(schema)
    failures = []

    shipped = sorted(presets.glob("*.json"))
    for f in shipped:
        errors = list(validator.iter_errors(load(f)))
        if errors:
            failures.append(f"{f.name}: shipped preset refused by the schema: {errors[0].message}")

    bad = sorted(catalogue.glob("*.json"))
    refused = 0
    for f in bad:
        try:
            valid = validator.is_valid(load(f))
        except NotJson:
            valid = False
        if f.name in CANNOT_TELL:
            if not valid:
                failures.append(f"{f.name}: listed as 'the schema cannot tell' but the schema refuses it")
        elif valid:
            failures.append(f"{f.name}: the schema accepts this bad preset (refuse it, or list in CANNOT_TELL why not)")
        else:
            refused += 1
    for name in CANNOT_TELL:
        if not (catalogue / name).exists():
            failures.append(f"{name}: listed in CANNOT_TELL but not in the catalogue")

    if not shipped or not bad:
        failures.append("no presets or no catalogue files found")
    for line in failures:
        print(line)
    if failures:
        return 1
    print(f"ok: {len(shipped)} shipped presets valid; {refused} of {len(bad)} bad presets refused by the schema, "
          f"{len(CANNOT_TELL)} it cannot tell")
    return 0


if __name__ == "__main__":
    sys.exit(main())

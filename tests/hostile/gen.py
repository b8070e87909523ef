#!/usr/bin/env python3
"""Writes one hostile preset to stdout: gen.py KIND SIZE.

Each kind grows with SIZE the way an attacker would grow it, so that a test at one size shows
whether time and memory grow linearly:
  deep N       objects/arrays nested N levels inside "description"
  keys N       N unknown keys in the room section
  overflow N   a string of N bytes, then 100 numbers too large for a double
  events N     N particles bouncing without loss in a 20 cm room (about 15 events per second each)
  big N        an emitter of N particles and 1000 variants (memory far past the machine)
  dt X         a one-ball preset with integrator dt X (a decimal string)
  name         a preset whose name holds terminal escape codes
  emitter N    an emitter of N particles (memory per particle)
"""
import json
import sys

HEAD = '{"format": "particle-lab-preset", "version": 1, "room": {"center": [0, 0, 0], "size": [2, 2, 2]}, '
BALL = '"particles": [{"position": [0, 0, 0]}]'


def main():
    kind = sys.argv[1]
    arg = sys.argv[2] if len(sys.argv) > 2 else "0"
    out = sys.stdout
    if kind == "deep":
        n = int(arg)
        out.write(HEAD + BALL + ', "description": ' + "[" * n + "]" * n + "}")
    elif kind == "keys":
        n = int(arg)
        keys = ", ".join('"k%d": 0' % i for i in range(n))
        out.write('{"format": "particle-lab-preset", "version": 1, "room": {"center": [0, 0, 0], '
                  '"size": [2, 2, 2], ' + keys + "}, " + BALL + "}")
    elif kind == "overflow":
        n = int(arg)
        numbers = ", ".join('"o%d": 1e400' % i for i in range(100))
        out.write(HEAD + BALL + ', "description": "' + "x" * n + '", "world": {' + numbers + "}}")
    elif kind == "events":
        n = int(arg)
        out.write('{"format": "particle-lab-preset", "version": 1, "room": {"center": [0, 0, 0], '
                  '"size": [0.2, 0.2, 0.2]}, "contact": {"restitution": 1, "friction": 0, "rest_speed": 0.0001}, '
                  '"integrator": {"method": "semi_implicit_euler", "dt": 0.001}, '
                  '"emitter": {"count": %d, "seed": 1, "region_min": [-0.08, -0.08, -0.08], '
                  '"region_max": [0.08, 0.08, 0.08], "speed_min": 1, "speed_max": 2, '
                  '"radius_min": 0.01, "radius_max": 0.01}}' % n)
    elif kind in ("big", "emitter", "colliding"):
        n = int(arg)
        variants = ""
        if kind == "big":
            variants = ', "variants": [' + ", ".join('{"label": "v%d"}' % i for i in range(1000)) + "]"
        if kind == "colliding":  # 64 variants, collisions on: the collision pass's memory dominates
            variants = ', "collisions": {"enabled": true}, "variants": [' + ", ".join(
                '{"label": "v%d"}' % i for i in range(64)) + "]"
        out.write(HEAD + '"emitter": {"count": %d, "radius_min": 0.001, "radius_max": 0.001}' % n + variants + "}")
    elif kind == "dt":
        out.write(HEAD + BALL + ', "integrator": {"method": "semi_implicit_euler", "dt": %s}}' % arg)
    elif kind == "name":
        out.write(HEAD + BALL + ", \"name\": " + json.dumps("evil\x1b[2J\x1b]0;pwned\x07\rname") + "}")
    else:
        sys.exit("gen.py: unknown kind " + kind)


if __name__ == "__main__":
    main()

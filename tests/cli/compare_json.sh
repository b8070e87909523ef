#!/usr/bin/env bash
# `compare --json` parses, has one entry per variant with the baseline's differences zero, and
# shows the physical ordering of the drag models (apex and range fall as drag grows).
set -euo pipefail
bin=$1 src=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

"$bin" compare "$src/presets/drag_models.json" --duration 3 --json --baseline "quadratic (Cd 0.47)" > "$tmp/c.json"
python3 - "$tmp/c.json" <<'PY'
import json, sys
c = json.load(open(sys.argv[1]))
v = {x["label"]: x for x in c["variants"]}
assert len(v) == 4, v.keys()
assert c["baseline"] == "quadratic (Cd 0.47)"
base = v["quadratic (Cd 0.47)"]["difference_to_baseline"]
assert base["apex_height_m"] == 0 and base["bounces"] == 0, base
none, quad = v["none"]["particle"], v["quadratic (Cd 0.47)"]["particle"]
assert none["apex_height_m"] > quad["apex_height_m"]
assert none["range_at_first_impact_m"] > quad["range_at_first_impact_m"]
assert v["none"]["all_particles"]["lost_to_drag_J"] == 0
assert v["quadratic (Cd 0.47)"]["all_particles"]["lost_to_drag_J"] > 0
assert v["none"]["cost_s_per_s"] > 0
d = v["none"]["difference_to_baseline"]
assert abs(d["apex_height_m"] - (none["apex_height_m"] - quad["apex_height_m"])) < 1e-12
PY

"$bin" compare "$src/presets/drag_models.json" --duration 1 > "$tmp/table.txt"
grep -q "difference to 'none'" "$tmp/table.txt" || { cat "$tmp/table.txt"; exit 1; }
echo ok

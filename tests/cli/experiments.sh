#!/usr/bin/env bash
# The README's three worked experiments ("Experiments"). Their expected values live in the
# presets' "expect" lists: each expected value must be the closed form the README gives (so the
# preset cannot drift from the physics), and `particle-lab compare --json` must report every one
# met, within the tolerance the preset states.
set -euo pipefail
bin=$1 src=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

"$bin" compare "$src/presets/drop_restitution_0.8.json" --duration 2 --json > "$tmp/drop.json"
"$bin" compare "$src/presets/friction_slide.json" --duration 3 --json > "$tmp/slide.json"
"$bin" compare "$src/presets/launch_velocities.json" --duration 2 --json > "$tmp/throw.json"
python3 - "$tmp" <<'PY'
import json, math, sys
g = 9.81
# The closed forms, by (preset, quantity):
# 1. Drop from h = 2 m: first impact at t0 = sqrt(2 h / g).
# 2. Friction slide at v = 4 m/s, mu = 0.3: stops after v^2 / (2 mu g) and v / (mu g).
# 3. Particle 2 thrown at (4, 6, 0) m/s from 0.5 m over the floor (centre 0.467 m above its
#    landing height d): apex 0.5 + vy^2 / (2 g), flight (vy + sqrt(vy^2 + 2 g d)) / g, range vx t.
flight = (6.0 + math.sqrt(36.0 + 2 * g * (0.5 - 0.033))) / g
closed = {
    ("drop", "time_of_flight_s"): math.sqrt(2 * 2.0 / g),
    ("slide", "final_range_m"): 4.0**2 / (2 * 0.3 * g),
    ("slide", "time_to_rest_s"): 4.0 / (0.3 * g),
    ("throw", "apex_height_m"): 0.5 + 36.0 / (2 * g),
    ("throw", "time_of_flight_s"): flight,
    ("throw", "range_at_first_impact_m"): 4.0 * flight,
}
failed = []
seen = set()
for name in ("drop", "slide", "throw"):
    expectations = json.load(open(f"{sys.argv[1]}/{name}.json"))["expectations"]
    for e in expectations:
        key = (name, e["quantity"])
        seen.add(key)
        print(f"{name}: {e['quantity']} measured {e['measured']:.4f}, expected {e['expected']} +- {e['tolerance']}")
        if key not in closed:
            failed.append(f"{key}: no closed form in this test")
        elif abs(e["expected"] - closed[key]) > 1e-4:
            failed.append(f"{key}: the preset expects {e['expected']}, the closed form gives {closed[key]:.5f}")
        if not e["met"]:
            failed.append(f"{key}: measured {e['measured']} is not within {e['tolerance']} of {e['expected']}")
for key in closed.keys() - seen:
    failed.append(f"{key}: the preset has no expectation for it")
for f in failed:
    print("FAIL:", f)
sys.exit(1 if failed else 0)
PY
echo "OK"

#!/usr/bin/env bash
# The README's three worked experiments ("Experiments"): what `particle-lab compare` measures
# agrees with the closed forms the README gives, within the tolerances it states.
set -euo pipefail
bin=$1 src=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

"$bin" compare "$src/presets/drop_restitution_0.8.json" --duration 2 --json > "$tmp/drop.json"
"$bin" compare "$src/presets/friction_slide.json" --duration 3 --json > "$tmp/slide.json"
"$bin" compare "$src/presets/launch_velocities.json" --duration 2 --particle 2 --json > "$tmp/throw.json"
python3 - "$tmp" <<'PY'
import json, math, sys
g = 9.81
def metrics(name):
    return json.load(open(f"{sys.argv[1]}/{name}.json"))["variants"][0]["particle"]
checks = []
def expect(what, measured, expected, tolerance):
    checks.append((what, measured, expected, tolerance, abs(measured - expected) <= tolerance))

# 1. Drop from h = 2 m: first impact at t0 = sqrt(2 h / g).
expect("drop: first impact (s)", metrics("drop")["time_of_flight_s"], math.sqrt(2 * 2.0 / g), 0.002)
# 2. Friction slide at v = 4 m/s, mu = 0.3: stops after v^2 / (2 mu g) and v / (mu g).
slide = metrics("slide")
expect("slide: distance (m)", slide["final_range_m"], 4.0**2 / (2 * 0.3 * g), 0.01)
expect("slide: time to rest (s)", slide["time_to_rest_s"], 4.0 / (0.3 * g), 0.01)
# 3. Throw at (4, 6, 0) m/s from 0.5 m over the floor (centre 0.467 m above its landing height):
#    apex 0.5 + vy^2 / (2 g) over the floor, flight (vy + sqrt(vy^2 + 2 g d)) / g, range vx t.
throw = metrics("throw")
flight = (6.0 + math.sqrt(36.0 + 2 * g * (0.5 - 0.033))) / g
expect("throw: apex over the floor (m)", throw["apex_height_m"], 0.5 + 36.0 / (2 * g), 0.01)
expect("throw: time of flight (s)", throw["time_of_flight_s"], flight, 0.005)
expect("throw: range (m)", throw["range_at_first_impact_m"], 4.0 * flight, 0.02)
bad = [c for c in checks if not c[4]]
for what, measured, expected, tolerance, _ in checks:
    print(f"{what}: measured {measured:.4f}, expected {expected:.4f} +- {tolerance}")
sys.exit(1 if bad else 0)
PY
echo "OK"

#!/usr/bin/env bash
# `run --out`: the trajectory CSV has the documented header, one row per particle for the initial
# state, every K-th step and the final state at exactly t = duration (no duplicate final row),
# per variant on its own step grid; height and speed are consistent with the state.
set -euo pipefail
bin=$1 src=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# Variants at dt = 0.04 ... 0.0025 s: each writes steps + 1 rows, the last at t = 0.4.
"$bin" run "$src/presets/dt_ladder.json" --duration 0.4 --out "$tmp/ladder.csv"
python3 - "$tmp/ladder.csv" <<'PY'
import csv, math, sys
rows = list(csv.reader(open(sys.argv[1])))
assert rows[0] == "t,variant,particle,x,y,z,vx,vy,vz,speed,height,kinetic_energy".split(","), rows[0]
by_variant = {}
for r in rows[1:]:
    by_variant.setdefault((r[1], r[2]), []).append(r)
expected = {"dt 0.04 s": 11, "dt 0.02 s": 21, "dt 0.01 s": 41, "dt 0.005 s": 81, "dt 0.0025 s": 161}
for (variant, particle), rs in by_variant.items():
    assert len(rs) == expected[variant], (variant, len(rs))
    assert rs[0][0] == "0", rs[0]
    assert rs[-1][0] == "0.4", (variant, rs[-1][0])  # exactly the duration
    times = [float(r[0]) for r in rs]
    assert all(a < b for a, b in zip(times, times[1:])), variant  # increasing, no duplicate final row
    for r in rs:
        vx, vy, vz, speed = map(float, r[6:10])
        assert math.isclose(speed, math.sqrt(vx*vx + vy*vy + vz*vz), rel_tol=1e-12, abs_tol=1e-300), r
assert set(v for v, _ in by_variant) == set(expected), by_variant.keys()
PY

# --every 7 over 500 steps: t = 0, 7 dt, ..., 497 dt, then the final state at t = 1.
"$bin" run "$src/presets/default.json" --duration 1 --every 7 --out "$tmp/every.csv"
python3 - "$tmp/every.csv" <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
particles = len(set(r["particle"] for r in rows))
times = sorted(set(float(r["t"]) for r in rows))
assert len(times) == 1 + 71 + 1, len(times)
assert len(rows) == len(times) * particles
assert rows[-1]["t"] == "1", rows[-1]["t"]
assert abs(times[-2] - 497 * 0.002) < 1e-12, times[-2]
PY

# Height is measured from the floor (room centre y 0, size 6: floor at y = -3).
"$bin" run "$src/presets/drop_restitution_0.8.json" --duration 0.5 --out "$tmp/drop.csv"
python3 - "$tmp/drop.csv" <<'PY'
import csv, sys
for r in csv.DictReader(open(sys.argv[1])):
    assert abs(float(r["height"]) - (float(r["y"]) + 3.0)) < 1e-12, r
PY

# A duration that is not a whole number of some variant's steps is refused with exit 2.
set +e
"$bin" run "$src/presets/dt_ladder.json" --duration 0.41 --out "$tmp/bad.csv" 2> "$tmp/err.txt"
code=$?
set -e
[ "$code" -eq 2 ] || { echo "expected exit 2 for --duration 0.41, got $code"; exit 1; }
grep -q -- "--duration" "$tmp/err.txt" || { echo "error does not name --duration:"; cat "$tmp/err.txt"; exit 1; }
echo ok

#!/usr/bin/env bash
# `run --out`: the trajectory CSV has the documented header (units in the names), one row per
# particle for the initial state, every K-th step and the final state at t = duration (no
# duplicate final row), per variant on its own step grid; t_s is step x dt; the variant column is
# the label and variant_index its index; height, speed and the energies are consistent with the
# state, mass and radius.
set -euo pipefail
bin=$1 src=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# Variants at dt = 0.04 ... 0.0025 s: each writes steps + 1 rows, the last at t = 0.4.
"$bin" run "$src/presets/dt_ladder.json" --duration 0.4 --out "$tmp/ladder.csv"
python3 - "$tmp/ladder.csv" <<'PY'
import csv, math, sys
rows = list(csv.reader(open(sys.argv[1])))
assert rows[0] == ("step,t_s,variant,variant_index,particle,mass_kg,radius_m,x_m,y_m,z_m,vx_m_s,vy_m_s,vz_m_s,"
                   "speed_m_s,height_m,kinetic_energy_J,potential_energy_J,total_energy_J").split(","), rows[0]
rows = [dict(zip(rows[0], r)) for r in rows[1:]]
by_variant = {}
for r in rows:
    by_variant.setdefault((r["variant"], r["particle"]), []).append(r)
expected = {"dt 0.04 s": (0, 0.04, 11), "dt 0.02 s": (1, 0.02, 21), "dt 0.01 s": (2, 0.01, 41),
            "dt 0.005 s": (3, 0.005, 81), "dt 0.0025 s": (4, 0.0025, 161)}
for (variant, particle), rs in by_variant.items():
    index, dt, count = expected[variant]
    assert len(rs) == count, (variant, len(rs))
    assert all(r["variant_index"] == str(index) for r in rs), variant
    assert [int(r["step"]) for r in rs] == list(range(count)), variant
    assert all(float(r["t_s"]) == int(r["step"]) * dt for r in rs), variant  # t = step x dt, bit for bit
    assert rs[0]["t_s"] == "0", rs[0]
    assert math.isclose(float(rs[-1]["t_s"]), 0.4, rel_tol=1e-12), (variant, rs[-1]["t_s"])  # the duration
    for r in rs:
        m, vx, vy, vz, speed = (float(r[k]) for k in ("mass_kg", "vx_m_s", "vy_m_s", "vz_m_s", "speed_m_s"))
        assert m == 0.057 and float(r["radius_m"]) == 0.033, r
        assert math.isclose(speed, math.sqrt(vx*vx + vy*vy + vz*vz), rel_tol=1e-12, abs_tol=1e-300), r
        assert math.isclose(float(r["kinetic_energy_J"]), 0.5 * m * speed * speed, rel_tol=1e-12, abs_tol=1e-300), r
        assert float(r["total_energy_J"]) == float(r["kinetic_energy_J"]) + float(r["potential_energy_J"]), r
assert set(v for v, _ in by_variant) == set(expected), by_variant.keys()
PY

# --every 7 over 500 steps: t = 0, 7 dt, ..., 497 dt, then the final state at t = 1.
"$bin" run "$src/presets/default.json" --duration 1 --every 7 --out "$tmp/every.csv"
python3 - "$tmp/every.csv" <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
particles = len(set(r["particle"] for r in rows))
times = sorted(set(float(r["t_s"]) for r in rows))
assert len(times) == 1 + 71 + 1, len(times)
assert len(rows) == len(times) * particles
assert rows[-1]["t_s"] == "1" and rows[-1]["step"] == "500", rows[-1]
assert abs(times[-2] - 497 * 0.002) < 1e-12, times[-2]
PY

# Height is measured from the floor (room centre y 0, size 6: floor at y = -3), and the potential
# energy is m g height (gravity -9.81 along y); with no drag the total energy is conserved up to
# the integrator's error before the first bounce.
"$bin" run "$src/presets/drop_restitution_0.8.json" --duration 0.5 --out "$tmp/drop.csv"
python3 - "$tmp/drop.csv" <<'PY'
import csv, math, sys
rows = list(csv.DictReader(open(sys.argv[1])))
for r in rows:
    assert abs(float(r["height_m"]) - (float(r["y_m"]) + 3.0)) < 1e-12, r
    pe = float(r["mass_kg"]) * 9.81 * float(r["height_m"])
    assert math.isclose(float(r["potential_energy_J"]), pe, rel_tol=1e-9, abs_tol=1e-12), (r, pe)
e0 = float(rows[0]["total_energy_J"])
assert all(abs(float(r["total_energy_J"]) - e0) < 1e-3 * e0 for r in rows if float(r["t_s"]) < 0.3), e0
PY

# A duration that is not a whole number of some variant's steps is refused with exit 2.
set +e
"$bin" run "$src/presets/dt_ladder.json" --duration 0.41 --out "$tmp/bad.csv" 2> "$tmp/err.txt"
code=$?
set -e
[ "$code" -eq 2 ] || { echo "expected exit 2 for --duration 0.41, got $code"; exit 1; }
grep -q -- "--duration" "$tmp/err.txt" || { echo "error does not name --duration:"; cat "$tmp/err.txt"; exit 1; }
echo ok

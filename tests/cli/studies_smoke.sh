#!/usr/bin/env bash
# accuracy, stability and advise run end to end and print well-formed CSV/JSON.
set -euo pipefail
bin=$1 src=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

"$bin" accuracy "$src/presets/drop_restitution_0.8.json" --methods semi_implicit_euler,rk4,dopri5 \
  --tol 1e-4,1e-8 --duration 1 --csv > "$tmp/acc.csv"
python3 - "$tmp/acc.csv" <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
assert len(rows) == 5 + 5 + 2, len(rows)
semi = [r for r in rows if r["method"] == "semi_implicit_euler"]
assert [float(r["dt_s"]) for r in semi] == [0.004, 0.002, 0.001, 0.0005, 0.00025]
assert 0.7 < float(semi[0]["observed_order"]) < 1.3, semi[0]["observed_order"]
assert all(r["bounce_time_error_s"] != "" for r in semi)  # the drop hits the floor at t = 0.64 s
assert all(r["tol"] != "" and r["adaptive"] == "1" for r in rows if r["method"] == "dopri5")
PY
"$bin" accuracy "$src/presets/default.json" --methods rk4 --json > "$tmp/acc.json"
python3 -c 'import json, sys; d = json.load(open(sys.argv[1])); assert d["orders"][0]["method"] == "rk4"' "$tmp/acc.json"

"$bin" stability --quick --json > "$tmp/stab.json"
python3 - "$tmp/stab.json" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
lim = [l for l in d["limits"] if l["method"] == "semi_implicit_euler" and l["k_per_s"] == 1000]
assert lim and abs(lim[0]["theoretical_dt_s"] - 0.002) < 1e-15, lim
assert lim[0]["first_unstable_dt_s"] is not None
assert {c["outcome"] for c in d["map"]} <= {"stable", "energy_growth", "nan", "escaped", "jitter", "tunnelled"}
assert len(d["sweep"]) > 0
PY
"$bin" stability "$src/presets/default.json" --quick > "$tmp/stab.txt"
grep -q "theory dt" "$tmp/stab.txt"

"$bin" advise "$src/presets/default.json" --json > "$tmp/adv.json"
python3 - "$tmp/adv.json" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
v = d["variants"][0]
assert [r["drag"] for r in v["runs"]][:4] == ["none", "linear", "quadratic", "sphere_re"]
assert v["reynolds_max"] > 1e3 and any("linear drag is wrong here" in s for s in v["verdicts"]), v["verdicts"]
c = v["collisions"]  # one particle: the collisions row is not judged
assert not c["applicable"] and c["mean_free_path_m"] is None and not c["recommended"], c
assert "collisions: one particle: nothing to collide with" in v["verdicts"], v["verdicts"]
PY

# Sixteen pool balls on a table: collisions recommended, with the estimate and the measured runs.
"$bin" advise "$src/presets/pool_break.json" --json > "$tmp/pool.json"
python3 - "$tmp/pool.json" <<'PY'
import json, math, sys
d = json.load(open(sys.argv[1]))
for v in d["variants"]:
    c = v["collisions"]
    assert c["applicable"] and c["particles"] == 16 and c["recommended"], c
    lam = 1 / (math.sqrt(2) * c["number_density_m3"] * c["cross_section_m2"])
    assert abs(c["mean_free_path_m"] - lam) < 1e-9 * lam, c
    run = {r["term"]: r for r in v["runs"]}["collisions"]
    assert run["matters"], run
    assert any(s.startswith("collisions matter: ") for s in v["verdicts"]), v["verdicts"]
PY

# A vertical drop: judged by landing time and impact speed, for drag (on in the air variant, off
# in the vacuum one), buoyancy and added mass (on: the foam ball is 0.64 of the air's density).
"$bin" advise "$src/presets/feather_vs_ball.json" --json > "$tmp/feather.json"
python3 - "$tmp/feather.json" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
assert d["tolerance_s"] == 1e-3 and d["tolerance_m_s"] == 1e-3 and d["relative_tolerance"] == 0, d
air, vacuum = d["variants"]
runs = {r["term"]: r for r in air["runs"]}
drag = runs["drag"]
assert drag["in_scene"] and drag["matters"], drag
lt = drag["metrics"]["landing_time_s"]
assert lt["beyond_tolerance"] and lt["difference"] > 1.0 and lt["particle"] == 0, lt
assert drag["metrics"]["landing_point_m"]["difference"] < 1e-6, drag  # straight down either way
assert air["cheapest_adequate_drag"] != "none"
assert any(s.startswith("drag matters: landing time +") for s in air["verdicts"]), air["verdicts"]
assert any(s.startswith("drag is off and would change nothing beyond tolerance") for s in vacuum["verdicts"]), vacuum["verdicts"]
b = runs["buoyancy"]
assert b["in_scene"] and b["matters"] and abs(air["density_ratio"][0] - 0.641) < 1e-3, (b, air["density_ratio"])
assert any(s.startswith("buoyancy matters: landing time +") and "rho_air/rho_particle = 0.641" in s for s in air["verdicts"])
m = runs["added mass"]
assert m["in_scene"] and m["matters"] and m["metrics"]["landing_time_s"]["difference"] > 0.05, m
assert any(s.startswith("added mass matters: landing time +") for s in air["verdicts"]), air["verdicts"]
PY

echo ok

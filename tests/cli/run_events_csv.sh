#!/usr/bin/env bash
# `run --events`: a drop with restitution 0.8 writes one bounce row per floor impact (rebound
# speed 0.8 of the impact speed) and ends with a rest row; `run` without --out prints the summary.
set -euo pipefail
bin=$1 src=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

preset="$src/presets/drop_restitution_0.8.json"
if [ ! -f "$preset" ]; then
  preset="$tmp/drop.json"
  cat > "$preset" <<'JSON'
{ "format": "particle-lab-preset", "version": 1, "name": "drop",
  "room": { "center": [0, 0, 0], "size": [10, 6, 10] },
  "world": { "gravity": [0, -9.81, 0] }, "drag": { "model": "none" },
  "contact": { "restitution": 0.8, "friction": 0, "rest_speed": 0.05 },
  "integrator": { "method": "semi_implicit_euler", "dt": 0.001 },
  "particles": [ { "position": [0, -0.967, 0], "velocity": [0, 0, 0], "mass": 0.057, "radius": 0.033 } ] }
JSON
fi

"$bin" run "$preset" --duration 7 --events "$tmp/events.csv" --out "$tmp/traj.csv"
python3 - "$tmp/events.csv" <<'PY'
import csv, math, sys
rows = list(csv.reader(open(sys.argv[1])))
assert rows[0] == "t_s,variant,variant_index,particle,wall,speed_in_m_s,speed_out_m_s,kind".split(","), rows[0]
events = [dict(zip(rows[0], r)) for r in rows[1:]]
bounces = [r for r in events if r["kind"] == "bounce"]
assert len(bounces) >= 10, len(bounces)
assert all(r["wall"] == "y_min" for r in bounces), bounces[:3]
assert all(r["variant"] == "" and r["variant_index"] == "0" for r in events), events[0]  # no variants: empty label
t0 = math.sqrt(2 * 2.0 / 9.81)  # first impact of a drop from 2 m
assert abs(float(bounces[0]["t_s"]) - t0) < 0.005, bounces[0]
for r in bounces:
    assert math.isclose(float(r["speed_out_m_s"]), 0.8 * float(r["speed_in_m_s"]), rel_tol=1e-12), r
times = [float(r["t_s"]) for r in events]
assert all(a <= b for a, b in zip(times, times[1:]))
assert events[-1]["kind"] == "rest" and float(events[-1]["speed_out_m_s"]) == 0.0, events[-1]
PY

"$bin" run "$preset" --duration 1 > "$tmp/summary.txt"
for word in "1 s" "events:" "energy" "residual" "force evaluations"; do
  grep -q -- "$word" "$tmp/summary.txt" || { echo "summary lacks '$word':"; cat "$tmp/summary.txt"; exit 1; }
done
echo ok

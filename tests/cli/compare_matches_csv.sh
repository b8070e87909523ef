#!/usr/bin/env bash
# The comparison metrics equal what an independent reader computes from the trajectory and
# events CSV of the same run: bounces, time of flight, time to rest and the final range. The apex
# and the range at the first impact are measured on the step's own trajectory (inside a step), so
# they lie within what a step can add to the recorded step ends: the apex at or above the highest
# recorded height by less than |a| dt^2 / 8 (a parabola between two step ends), the range within
# |a_h| dt^2 / 2 of the state before the impact's step extrapolated linearly to it.
set -euo pipefail
bin=$1 src=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

check() {  # preset duration
  "$bin" run "$1" --duration "$2" --out "$tmp/traj.csv" --events "$tmp/events.csv"
  "$bin" compare "$1" --duration "$2" --json > "$tmp/c.json"
  python3 - "$tmp/traj.csv" "$tmp/events.csv" "$tmp/c.json" <<'PY'
import csv, json, math, sys
traj = list(csv.DictReader(open(sys.argv[1])))
events = list(csv.DictReader(open(sys.argv[2])))
c = json.load(open(sys.argv[3]))
assert c["particle"] == 0
for v in c["variants"]:
    label, m, index = v["label"], v["particle"], str(v["variant_index"])
    rows = [r for r in traj if r["variant_index"] == index and r["particle"] == "0"]
    evs = [e for e in events if e["variant_index"] == index and e["particle"] == "0"]
    assert all(r["variant"] == label for r in rows + evs), label
    assert rows, label
    dt = float(rows[1]["t_s"]) - float(rows[0]["t_s"])
    bound = 50.0 * dt * dt  # |a| up to 100 m/s^2 (gravity and drag of these presets: far less)
    # Apex: at or above the highest recorded height (every step), by what a step can rise.
    recorded = max(float(r["height_m"]) for r in rows)
    assert recorded <= m["apex_height_m"] <= recorded + bound, (label, recorded, m["apex_height_m"])
    # Bounces: rebound events on a wall.
    assert sum(1 for e in evs if e["kind"] == "bounce" and e["wall"]) == m["bounces"], label
    impacts = [e for e in evs if e["kind"] in ("bounce", "rest") and e["wall"]]
    if impacts:
        t_hit = float(impacts[0]["t_s"])
        assert t_hit == m["time_of_flight_s"], (label, t_hit, m["time_of_flight_s"])
        assert impacts[0]["wall"] == m["first_impact_wall"]
        # The state before the step of the impact, extrapolated to it.
        before = max((r for r in rows if float(r["t_s"]) < t_hit), key=lambda r: float(r["t_s"]))
        s = t_hit - float(before["t_s"])
        x = float(before["x_m"]) + s * float(before["vx_m_s"])
        z = float(before["z_m"]) + s * float(before["vz_m_s"])
        r0 = rows[0]
        rng = math.hypot(x - float(r0["x_m"]), z - float(r0["z_m"]))
        assert abs(rng - m["range_at_first_impact_m"]) <= bound + 1e-12, (label, rng, m["range_at_first_impact_m"])
    else:
        assert m["time_of_flight_s"] is None
    last = rows[-1]
    final = math.hypot(float(last["x_m"]) - float(rows[0]["x_m"]), float(last["z_m"]) - float(rows[0]["z_m"]))
    assert abs(final - m["final_range_m"]) < 1e-12, label
    # Time to rest: the last event leaving it with zero velocity, if it ends at rest.
    stops = [e for e in evs if e["kind"] in ("rest", "stop") and float(e["speed_out_m_s"]) == 0.0]
    if float(last["speed_m_s"]) == 0.0 and stops:
        assert float(stops[-1]["t_s"]) == m["time_to_rest_s"], (label, stops[-1]["t_s"], m["time_to_rest_s"])
    else:
        assert m["time_to_rest_s"] is None, label
PY
}
check "$src/presets/drag_models.json" 3
check "$src/presets/drop_restitution_0.8.json" 7
check "$src/presets/restitution.json" 4
echo ok

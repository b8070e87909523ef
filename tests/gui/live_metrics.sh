#!/usr/bin/env bash
# The Compare tab's live metrics follow every step: after 2.5 s of drag_models.json (four drag
# models, one ball each) the GUI's apex, time of flight, range at the first impact and bounces of
# particle 0 are those `particle-lab compare` computes for the same duration. Sampled once per
# frame instead, the apex would fall on a frame boundary and the range at the first impact would
# be extrapolated from the frame before it.
# Usage: live_metrics.sh <particle-lab binary> <source dir>
APP=$1
SRC=$2
source "$SRC/tests/gui/gui_test_lib.bash"
make_workdir
STATE="$WORK/state.json"

"$APP" "$SRC/presets/drag_models.json" --frames 150 --fixed-frame-dt 0.016667 --dump-state "$STATE" \
    >"$WORK/app.out" 2>"$WORK/app.err" || fail "the app failed: $(cat "$WORK/app.err")"
json_check "$STATE" 'd["live_metrics"] is not None and len(d["live_metrics"]) == 4' "no live metrics for 4 variants"
json_check "$STATE" 'all(m["time_of_flight_s"] is not None for m in d["live_metrics"])' \
    "a ball has not reached a wall: the first impact is not tested"
T=$(json_get "$STATE" 'repr(d["t"])')
"$APP" compare "$SRC/presets/drag_models.json" --json --duration "$T" >"$WORK/compare.json" ||
    fail "particle-lab compare failed"

"$PYTHON" - "$STATE" "$WORK/compare.json" <<'PY' || fail "live metrics differ from particle-lab compare's"
import json, math, sys
gui = json.load(open(sys.argv[1]))["live_metrics"]
cli = [v["particle"] for v in json.load(open(sys.argv[2]))["variants"]]
assert len(gui) == len(cli), (len(gui), len(cli))
bad = []
for v, (g, c) in enumerate(zip(gui, cli)):
    for key in ("apex_height_m", "apex_time_s", "time_of_flight_s", "range_at_first_impact_m", "bounces"):
        if not math.isclose(g[key], c[key], rel_tol=1e-12, abs_tol=1e-12):
            bad.append(f"variant {v} {key}: GUI {g[key]!r}, compare {c[key]!r}")
print("\n".join(bad), file=sys.stderr)
sys.exit(1 if bad else 0)
PY
echo "OK"

#!/usr/bin/env bash
# The measuring tool: M turns it on; a click on the ball picks the ball where it is now, a second
# click on the ball later picks it again, and the distance and time between the two are those of
# the ball's two positions and times. Esc clears; a click where the ball was earlier snaps to the
# trail sample there (its time, not now). The toolbar's Measure button turns it off.
# Usage: measure_tool.sh <particle-lab binary> <source dir>
APP=$1
SRC=$2
source "$SRC/tests/gui/gui_test_lib.bash"
make_workdir
STATE="$WORK/state.json"

start_app "$SRC/presets/default.json" --frames 1000000 --dump-state "$STATE"
wait_for_state "$STATE" "d['t'] > 0.3 and 'view.measure' in d['widgets']" "the simulation does not run"
press space
wait_for_state "$STATE" "d['paused']" "space did not pause"
press m
wait_for_state "$STATE" "d['measure']['active'] and d['measure']['points'] == []" "M did not turn the measuring tool on"

# Clicks the ball where it is now; prints "t x y z" of the ball at the click.
click_ball() {
    dump_now "$STATE"
    json_check "$STATE" "d['variants'][0]['particles'][0]['screen'] is not None" "the ball is not on screen"
    local x y
    x=$(json_get "$STATE" "round(d['variants'][0]['particles'][0]['screen'][0])")
    y=$(json_get "$STATE" "round(d['variants'][0]['particles'][0]['screen'][1])")
    xdotool mousemove --window "$APP_WINDOW" "$x" "$y" click 1
    echo "$x $y"
}

read -r x1 y1 < <(click_ball)
cp "$STATE" "$WORK/first.json"
wait_for_state "$STATE" "len(d['measure']['points']) == 1" "a click on the ball did not pick a point"
"$PYTHON" - "$STATE" "$WORK/first.json" <<'PY' || fail "the first point is not the ball where it was"
import json, sys
d, first = json.load(open(sys.argv[1])), json.load(open(sys.argv[2]))
p = d["measure"]["points"][0]
ball = first["variants"][0]["particles"][0]["position"]
assert p["t"] == first["t"], (p["t"], first["t"])
assert max(abs(a - b) for a, b in zip(p["position"], ball)) < 1e-6, (p["position"], ball)
PY
json_check "$STATE" "d['selected_particle'] == 0" "the selection changed"

press space
wait_for_state "$STATE" "d['t'] > $(json_get "$WORK/first.json" 'd["t"]') + 0.4" "the simulation did not go on"
press space
wait_for_state "$STATE" "d['paused']" "space did not pause again"
click_ball >/dev/null
cp "$STATE" "$WORK/second.json"
wait_for_state "$STATE" "d['measure']['distance_m'] is not None" "a second click did not measure"
"$PYTHON" - "$STATE" "$WORK/first.json" "$WORK/second.json" <<'PY' || fail "the distance or time is not the ball's"
import json, math, sys
d, a, b = (json.load(open(f)) for f in sys.argv[1:4])
pa, pb = (x["variants"][0]["particles"][0]["position"] for x in (a, b))
m = d["measure"]
assert abs(m["distance_m"] - math.dist(pa, pb)) < 1e-5, (m["distance_m"], math.dist(pa, pb))
assert abs(m["time_s"] - (b["t"] - a["t"])) < 1e-9, (m["time_s"], b["t"] - a["t"])
PY

hold_key Escape
wait_for_state "$STATE" "d['measure']['points'] == [] and d['measure']['active']" "Esc did not clear the measurement"

# Where the ball was at the first click: now a trail sample, picked with its own time.
xdotool mousemove --window "$APP_WINDOW" "$x1" "$y1" click 1
wait_for_state "$STATE" "len(d['measure']['points']) == 1" "a click on the trail did not pick a point"
t1=$(json_get "$WORK/first.json" 'd["t"]')
json_check "$STATE" "abs(d['measure']['points'][0]['t'] - $t1) <= 0.011 and d['measure']['points'][0]['t'] < d['t'] - 0.3" \
    "the click on the trail did not snap to the sample there"

click_widget "$STATE" view.measure
wait_for_state "$STATE" "not d['measure']['active']" "the toolbar's Measure button did not turn the tool off"
quit_app
echo "OK"

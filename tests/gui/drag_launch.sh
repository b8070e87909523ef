#!/usr/bin/env bash
# Ctrl + left drag in the 3D view aims a launch from the particle: while dragging, the aim's tip
# sits under the cursor on the plane facing the camera and points the way the mouse went (right
# on screen = the camera's right, up = its up); release gives the particle exactly that
# velocity (and makes it the Launch section's); the camera does not move. Esc and a right-click
# cancel an aim: nothing is launched.
# Usage: drag_launch.sh <particle-lab binary> <source dir>
APP=$1
SRC=$2
source "$SRC/tests/gui/gui_test_lib.bash"
make_workdir
STATE="$WORK/state.json"

start_app "$SRC/presets/default.json" --frames 1000000 --dump-state "$STATE"
# Paused and reset: particle 0 stands still at its start, velocity (3, 4, 1) m/s.
press space
wait_for_state "$STATE" 'd["paused"]' "space did not pause"
press r
wait_for_state "$STATE" 'd["base_steps"] == 0 and d["variants"][0]["particles"][0]["screen"] is not None' \
    "no reset state with particle 0 on screen"
read -r px py < <(json_get "$STATE" '" ".join(str(round(c)) for c in d["variants"][0]["particles"][0]["screen"])')
camera=$(json_get "$STATE" 'd["view"]["camera"]')
start_velocity=$(json_get "$STATE" 'd["variants"][0]["particles"][0]["velocity"]')

# Drags from the particle by (dx, dy) pixels with Ctrl held at the press (let go right after:
# the gesture keeps its mode until the button is released). Leaves the button down.
aim_from_particle() {
    local dx=$1 dy=$2
    xdotool mousemove --window "$APP_WINDOW" "$px" "$py"
    xdotool keydown ctrl
    sleep 0.1
    xdotool mousedown 1
    sleep 0.1
    xdotool keyup ctrl
    for step in 1 2 3 4 5; do
        xdotool mousemove --window "$APP_WINDOW" $((px + dx * step / 5)) $((py + dy * step / 5))
        sleep 0.04
    done
}

# 1. Aim up and to the right, check the readout, release: launched.
dx=90; dy=-120
aim_from_particle "$dx" "$dy"
wait_for_state "$STATE" "d['view']['aim'] is not None and d['view']['aim']['cursor'] == [$((px + dx)), $((py + dy))]" \
    "Ctrl+drag from the particle did not start an aim that follows the cursor"
"$PYTHON" - "$STATE" "$dx" "$dy" <<'PY' || fail "the aim does not map the drag as documented ($(head -c 600 "$STATE"))"
import json, math, sys
d = json.load(open(sys.argv[1]))
dx, dy = float(sys.argv[2]), float(sys.argv[3])
aim, view = d["view"]["aim"], d["view"]
assert aim["particle"] == 0 and aim["variant"] == 0, aim
# The tip (particle + v * arrow time) projects onto the cursor.
assert math.dist(aim["tip_screen"], aim["cursor"]) < 1.5, aim
# It points the way the mouse moved: dx along the camera's right, -dy along its up.
want = [dx * r - dy * u for r, u in zip(view["right"], view["up"])]
v = aim["velocity"]
cos = sum(a * b for a, b in zip(v, want)) / (math.hypot(*v) * math.hypot(*want))
assert cos > 0.999, (cos, v, want)
# Up on screen is upwards in the room; the readout's angles describe the same vector.
assert aim["elevation_deg"] > 10.0, aim
assert math.isclose(aim["speed"], math.hypot(*v), rel_tol=1e-9), aim
assert math.isclose(math.degrees(math.atan2(v[1], math.hypot(v[0], v[2]))), aim["elevation_deg"], abs_tol=1e-6), aim
assert math.isclose(math.degrees(math.atan2(v[2], v[0])), aim["azimuth_deg"], abs_tol=1e-6), aim
# Ten-metre room: the arrow is the straight path in 1 s, a plausible throw speed, not clamped.
assert aim["arrow_time_s"] == 1.0 and 1.0 < aim["speed"] < 100.0 and not aim["clamped"], aim
PY
aimed=$(json_get "$STATE" 'd["view"]["aim"]["velocity"]')
xdotool mouseup 1
wait_for_state "$STATE" 'd["view"]["aim"] is None and d["status"].startswith("Launched particle 0")' \
    "releasing the aim did not launch"
"$PYTHON" - "$STATE" "$aimed" "$camera" <<'PY' || fail "the particle was not launched with the aimed velocity ($(head -c 600 "$STATE"))"
import ast, json, math, sys
d = json.load(open(sys.argv[1]))
aimed, camera = ast.literal_eval(sys.argv[2]), ast.literal_eval(sys.argv[3])
p = d["variants"][0]["particles"][0]
# Paused: the kick is the whole change, so the velocity is the aim's (the release frame's cursor
# is the last one aimed at).
assert all(math.isclose(a, b, rel_tol=1e-6, abs_tol=1e-9) for a, b in zip(p["velocity"], aimed)), (p, aimed)
assert all(math.isclose(a, b, rel_tol=1e-6, abs_tol=1e-9) for a, b in zip(d["launch_velocity"], aimed)), d["launch_velocity"]
assert d["view"]["camera"] == camera, "the aim drag moved the camera"
assert d["paused"] and not d["dirty"] and d["selected_particle"] == 0, d
PY
# Running again, the particle flies the way it was aimed: up at first.
y0=$(json_get "$STATE" 'd["variants"][0]["particles"][0]["position"][1]')
press space
wait_for_state "$STATE" "not d['paused'] and d['t'] > 0.1 and d['variants'][0]['particles'][0]['position'][1] > $y0 + 0.2" \
    "the launched particle does not rise"

# 2. Esc cancels: the velocity the particle has stays.
press space
press r
wait_for_state "$STATE" "d['paused'] and d['base_steps'] == 0 and d['variants'][0]['particles'][0]['velocity'] == $start_velocity" \
    "no paused reset state"
aim_from_particle -100 -60
wait_for_state "$STATE" 'd["view"]["aim"] is not None' "the second aim did not start"
press Escape
wait_for_state "$STATE" 'd["view"]["aim"] is None' "Esc did not cancel the aim"
xdotool mouseup 1
sleep 0.3
dump_now "$STATE"
json_check "$STATE" "d['variants'][0]['particles'][0]['velocity'] == $start_velocity and d['view']['camera'] == $camera" \
    "a cancelled aim launched the particle or moved the camera"

# 3. A right-click during the aim cancels it too.
aim_from_particle 80 40
wait_for_state "$STATE" 'd["view"]["aim"] is not None' "the third aim did not start"
xdotool click 3
wait_for_state "$STATE" 'd["view"]["aim"] is None' "a right-click did not cancel the aim"
xdotool mouseup 1
sleep 0.3
dump_now "$STATE"
json_check "$STATE" "d['variants'][0]['particles'][0]['velocity'] == $start_velocity and d['view']['camera'] == $camera" \
    "an aim cancelled by right-click launched the particle or moved the camera"

quit_app
echo "OK"

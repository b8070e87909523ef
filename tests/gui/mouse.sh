#!/usr/bin/env bash
# Real mouse input on the 3D view: a click selects the particle under the cursor; a left drag
# orbits and the wheel zooms, but only over the view (a drag that starts on a panel leaves the
# camera alone); keys 2 and 0 give the top view and the framing view; the camera is remembered
# for the next run, and ImGui's layout file is kept in the config directory.
# Usage: mouse.sh <particle-lab binary> <source dir>
APP=$1
SRC=$2
source "$SRC/tests/gui/gui_test_lib.bash"
make_workdir
STATE="$WORK/state.json"
PRESET="$SRC/presets/launch_velocities.json"

start_app "$PRESET" --frames 1000000 --dump-state "$STATE"
# Paused and reset, the five balls stand on their start line 1 m apart: a deterministic target.
press space
wait_for_state "$STATE" 'd["paused"]' "space did not pause"
press r
wait_for_state "$STATE" 'd["base_steps"] == 0 and d["variants"][0]["particles"][3]["screen"] is not None' \
    "no reset state with particle 3 on screen"
camera() { json_get "$STATE" 'd["view"]["camera"]'; }

# Click particle 3.
read -r px py < <(json_get "$STATE" '" ".join(str(round(c)) for c in d["variants"][0]["particles"][3]["screen"])')
xdotool mousemove --window "$APP_WINDOW" "$px" "$py" click 1
wait_for_state "$STATE" 'd["selected_particle"] == 3 and d["selected_variant"] == 0' "clicking particle 3 did not select it"

# Left drag in the middle of the 3D view orbits the camera; the selection stays.
read -r vx vy vw vh < <(json_get "$STATE" '" ".join(str(round(c)) for c in d["view"]["panes"][0])')
cx=$((vx + vw / 2)); cy=$((vy + vh / 4))
before=$(camera)
xdotool mousemove --window "$APP_WINDOW" "$cx" "$cy" mousedown 1
for step in 1 2 3 4 5 6; do xdotool mousemove --window "$APP_WINDOW" $((cx + 20 * step)) $((cy + 5 * step)); sleep 0.05; done
xdotool mouseup 1
wait_for_state "$STATE" "d['view']['camera'] != $before" "a drag over the view did not orbit"
json_check "$STATE" 'd["selected_particle"] == 3' "the drag changed the selection"

# A drag that starts on the plots panel (right of the view) must not move the camera.
dump_now "$STATE"
before=$(camera)
px=$((vx + vw + 60)); py=$((vy + vh / 2))
xdotool mousemove --window "$APP_WINDOW" "$px" "$py" mousedown 1
for step in 1 2 3 4 5 6; do xdotool mousemove --window "$APP_WINDOW" $((px - 30 * step)) "$py"; sleep 0.05; done
xdotool mouseup 1
sleep 0.3
dump_now "$STATE"
json_check "$STATE" "d['view']['camera'] == $before" "a drag from a panel moved the camera"

# Wheel up over the view zooms in.
distance=$(json_get "$STATE" 'd["view"]["camera"]["distance"]')
xdotool mousemove --window "$APP_WINDOW" "$cx" "$cy" click 4
wait_for_state "$STATE" "d['view']['camera']['distance'] < $distance" "the wheel did not zoom"

press 2
wait_for_state "$STATE" 'd["view"]["camera"]["pitch"] > 1.57' "key 2 did not give the top view"
press 0
wait_for_state "$STATE" '0.1 < d["view"]["camera"]["pitch"] < 1.0' "key 0 did not reset the view"
xdotool mousemove --window "$APP_WINDOW" "$cx" "$cy" click 5 click 5
wait_for_state "$STATE" "d['view']['camera']['distance'] > $distance" "the wheel did not zoom out"
remembered=$(camera)

quit_app
[ -s "$XDG_CONFIG_HOME/particle-lab/camera.txt" ] || fail "the camera was not saved"
[ -s "$XDG_CONFIG_HOME/particle-lab/imgui.ini" ] || fail "the layout (imgui.ini) was not saved"

# The next run starts with the camera the last one ended with.
timeout 60 "$APP" "$PRESET" --frames 2 --fixed-frame-dt 0.016 --dump-state "$STATE" 2>"$WORK/err2.txt" ||
    fail "second run failed: $(cat "$WORK/err2.txt")"
"$PYTHON" - "$STATE" "$remembered" <<'PY' || fail "the camera was not restored"
import ast, json, math, sys
got, want = json.load(open(sys.argv[1]))["view"]["camera"], ast.literal_eval(sys.argv[2])
for key in ("yaw", "pitch", "distance"):
    assert math.isclose(got[key], want[key], rel_tol=1e-6, abs_tol=1e-6), (key, got, want)
assert all(math.isclose(a, b, abs_tol=1e-6) for a, b in zip(got["target"], want["target"])), (got, want)
PY
echo "OK"

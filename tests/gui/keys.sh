#!/usr/bin/env bash
# Real key presses (xdotool) drive the running app; its state is read back through SIGUSR1 dumps:
# space pauses, N steps once, R resets, L launches particle 0 again with the launch velocity,
# H shows help and Esc closes it, space resumes, Ctrl+Q quits cleanly with a final dump.
# Usage: keys.sh <particle-lab binary> <source dir>
APP=$1
SRC=$2
source "$SRC/tests/gui/gui_test_lib.bash"
make_workdir
STATE="$WORK/state.json"
PRESET="$SRC/presets/default.json"

start_app "$PRESET" --frames 1000000 --dump-state "$STATE"
wait_for_state "$STATE" 'd["t"] > 0.2 and not d["paused"]' "the simulation does not run"

press space
wait_for_state "$STATE" 'd["paused"]' "space did not pause"
t_paused=$(json_get "$STATE" 'd["base_steps"]')
sleep 0.3
dump_now "$STATE"
json_check "$STATE" "d['base_steps'] == $t_paused" "time advanced while paused"

press n
wait_for_state "$STATE" "d['base_steps'] == $t_paused + 1" "N did not take exactly one step"

press r
wait_for_state "$STATE" 'd["base_steps"] == 0 and d["t"] == 0.0 and d["paused"]' "R did not reset (or unpaused)"
# After a reset the particles are back at the preset's initial state.
"$PYTHON" - "$STATE" "$PRESET" <<'PY' || fail "reset state differs from the preset"
import json, sys
d, preset = json.load(open(sys.argv[1])), json.load(open(sys.argv[2]))
for want, got in zip(preset["particles"], d["variants"][0]["particles"]):
    assert got["position"] == want["position"], (got, want)
    assert got["velocity"] == want["velocity"], (got, want)
PY

# Let it fly a while, then launch again: particle 0 is back at its start with the launch velocity.
press space
wait_for_state "$STATE" 'd["t"] > 0.5' "the simulation did not resume"
press space
wait_for_state "$STATE" 'd["paused"]' "space did not pause again"
press l
"$PYTHON" - "$STATE" "$PRESET" <<'PY' >"$WORK/launch_condition"
import json, sys
preset = json.load(open(sys.argv[2]))
p0 = preset["particles"][0]["position"]
print(f'all(v["particles"][0]["position"] == {p0} and v["particles"][0]["velocity"] == d["launch_velocity"] '
      f'for v in d["variants"]) and d["t"] > 0.5')
PY
wait_for_state "$STATE" "$(cat "$WORK/launch_condition")" "L did not launch particle 0 again"

press h
wait_for_state "$STATE" 'd["show_help"]' "H did not open the help"
press Escape
wait_for_state "$STATE" 'not d["show_help"]' "Esc did not close the help"

quit_app
json_check "$STATE" 'd["paused"] and d["t"] > 0.5' "final dump does not show the last state"
echo "OK"

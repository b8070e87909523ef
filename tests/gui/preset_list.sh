#!/usr/bin/env bash
# The preset list with the mouse: a single click only marks an entry; a double-click loads it
# (the session holds that preset, not dirty, from t = 0, running).
# Usage: preset_list.sh <particle-lab binary> <source dir>
APP=$1
SRC=$2
source "$SRC/tests/gui/gui_test_lib.bash"
make_workdir
STATE="$WORK/state.json"
ONCE=dt_ladder
TWICE=drop_restitution_0.8

start_app "$SRC/presets/default.json" --frames 1000000 --dump-state "$STATE"
wait_for_state "$STATE" "'preset.$ONCE' in d['widgets'] and 'preset.$TWICE' in d['widgets'] and d['t'] > 0.2" \
    "the preset list does not show $ONCE and $TWICE"

read -r x y < <(widget_center "$STATE" "preset.$ONCE")
xdotool mousemove --window "$APP_WINDOW" "$x" "$y" click 1
sleep 0.6
dump_now "$STATE"
json_check "$STATE" 'd["preset"].endswith("default.json")' "a single click on $ONCE loaded it"

read -r x y < <(widget_center "$STATE" "preset.$TWICE")
# Dear ImGui 1.86 reads the mouse once per frame (no input queue): two clicks inside one frame
# are one click. 150 ms apart they fall in different frames unless a frame takes that long, and
# stay within ImGui's 0.30 s double-click time unless a frame takes twice that (a loaded machine
# took longer than 90 ms per frame, and the double-click was lost).
xdotool mousemove --window "$APP_WINDOW" "$x" "$y" click --repeat 2 --delay 150 1
wait_for_state "$STATE" "d['preset'].endswith('$TWICE.json')" "a double-click on $TWICE did not load it"
json_check "$STATE" 'not d["dirty"] and d["error_popup"] == "" and d["t"] < 0.5' \
    "the loaded preset is dirty, shows an error or did not start from t = 0"
t_loaded=$(json_get "$STATE" 'd["t"]')
wait_for_state "$STATE" "d['t'] > $t_loaded + 0.2" "the loaded preset does not run"

quit_app
echo "OK"

#!/usr/bin/env bash
# The Warnings tab with the mouse: drag_models.json warns at once (Stokes drag far outside its
# Reynolds range in the "linear (Stokes)" variant); clicking the tab shows the warnings, and
# clicking the first row selects that variant and particle for the Inspector.
# Usage: warnings_tab.sh <particle-lab binary> <source dir>
APP=$1
SRC=$2
source "$SRC/tests/gui/gui_test_lib.bash"
make_workdir
STATE="$WORK/state.json"

start_app "$SRC/presets/drag_models.json" --frames 1000000 --dump-state "$STATE"
wait_for_state "$STATE" 'len(d["warnings"]) > 0 and "tab.warnings" in d["widgets"]' "no warning, or no Warnings tab drawn"
read -r want_v want_p < <(json_get "$STATE" '"%d %d" % (d["warnings"][0]["variant"], d["warnings"][0]["particle"])')
[ "$(json_get "$STATE" 'd["selected_variant"]')" != "$want_v" ] ||
    fail "variant $want_v is selected before the click: the test would prove nothing"

read -r tx ty < <(widget_center "$STATE" tab.warnings)
xdotool mousemove --window "$APP_WINDOW" "$tx" "$ty" click 1
wait_for_state "$STATE" '"warnings.row0" in d["widgets"]' "clicking the Warnings tab did not show its rows"
read -r rx ry < <(widget_center "$STATE" warnings.row0)
xdotool mousemove --window "$APP_WINDOW" "$rx" "$ry" click 1
wait_for_state "$STATE" "d['selected_variant'] == $want_v and d['selected_particle'] == $want_p" \
    "clicking the first warning did not select variant $want_v, particle $want_p"

quit_app
echo "OK"

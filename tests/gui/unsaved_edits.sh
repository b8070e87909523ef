#!/usr/bin/env bash
# An unsaved edit is never thrown away without asking: Revert, Ctrl+O (open by path), a
# double-click in the preset list and its Load button each open the unsaved-changes dialog.
# Cancel keeps the edit (still dirty, the edited value, the same preset); Discard replaces the
# scene with the file (not dirty, the file's value).
# Usage: unsaved_edits.sh <particle-lab binary> <source dir>
APP=$1
SRC=$2
source "$SRC/tests/gui/gui_test_lib.bash"
make_workdir
STATE="$WORK/state.json"
DEFAULT="$SRC/presets/default.json"
TARGET="$SRC/presets/launch_velocities.json"
LISTED=dt_ladder
EDITED_DT=0.004  # every preset used here has another dt

# Waits for the dialog asking about `kind`, then clicks its button `answer` (cancel, discard).
answer_dialog() {
    local kind=$1 answer=$2
    wait_for_state "$STATE" "d['pending'] == '$kind' and 'unsaved.$answer' in d['widgets']" \
        "no unsaved-changes dialog for $kind"
    sleep 0.3  # the dialog settles its size and place on its first frames; click where it ends up
    dump_now "$STATE"
    click_widget "$STATE" "unsaved.$answer"
    wait_for_state "$STATE" 'd["pending"] is None' "$answer did not close the dialog for $kind"
}

# Cancel kept the edit on `preset`.
check_kept() {
    local what=$1 preset=$2
    sleep 0.3  # a wrongly performed load would show by now
    dump_now "$STATE"
    json_check "$STATE" "d['dirty'] and d['scene_dt'] == $EDITED_DT and d['preset'] == '$preset' and d['error_popup'] == ''" \
        "Cancel on $what did not keep the edit"
}

# Discard replaced the scene with `preset` as its file says (the list shows the build's copy of
# a shipped preset, hence the match on the file name).
check_replaced() {
    local what=$1 preset=$2 dt
    dt=$(json_get "$preset" 'd["integrator"]["dt"]')
    wait_for_state "$STATE" "d['preset'].endswith('/$(basename "$preset")') and not d['dirty'] and d['scene_dt'] == $dt and d['error_popup'] == ''" \
        "Discard on $what did not load $preset"
}

start_app "$DEFAULT" --frames 1000000 --dump-state "$STATE"
wait_for_state "$STATE" "d['t'] > 0.2 and 'time.dt' in d['widgets'] and 'preset.revert' in d['widgets'] and 'preset.$LISTED' in d['widgets']" \
    "the default preset does not run or its panel is not shown"

# Revert.
edit_dt
click_widget "$STATE" preset.revert
answer_dialog revert cancel
check_kept Revert "$DEFAULT"
click_widget "$STATE" preset.revert
answer_dialog revert discard
check_replaced Revert "$DEFAULT"

# Ctrl+O: the path typed, Enter.
edit_dt
open_by_path "$TARGET" "$STATE"
answer_dialog open cancel
check_kept Ctrl+O "$DEFAULT"
open_by_path "$TARGET" "$STATE"
answer_dialog open discard
check_replaced Ctrl+O "$TARGET"

# The preset list: a double-click, then the Load button (the double-click selected the entry).
edit_dt
read -r x y < <(widget_center "$STATE" "preset.$LISTED")
# Two clicks 150 ms apart: Dear ImGui 1.86 reads the mouse once per frame (see preset_list.sh).
xdotool mousemove --window "$APP_WINDOW" "$x" "$y" click --repeat 2 --delay 150 1
answer_dialog open cancel
check_kept "a double-click in the preset list" "$TARGET"
click_widget "$STATE" preset.load
answer_dialog open discard
check_replaced "the Load button" "$SRC/presets/$LISTED.json"

# Nothing is unsaved now: Ctrl+Q quits without asking.
quit_app
echo "OK"

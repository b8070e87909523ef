#!/usr/bin/env bash
# The split view's pane choice with the mouse: integrators.json has six variants; Split shows all
# six (up to nine fit), and unticking one in the panes menu beside the Split button leaves five
# panes without it.
# Usage: split_panes.sh <particle-lab binary> <source dir>
APP=$1
SRC=$2
source "$SRC/tests/gui/gui_test_lib.bash"
make_workdir
STATE="$WORK/state.json"

start_app "$SRC/presets/integrators.json" --frames 1000000 --dump-state "$STATE"
wait_for_state "$STATE" '"view.split" in d["widgets"]' "no Split button drawn"
json_check "$STATE" 'd["view"]["pane_variants"] == [None]' "the view is split before Split was clicked"
click_widget "$STATE" view.split
wait_for_state "$STATE" 'd["view"]["pane_variants"] == [0, 1, 2, 3, 4, 5]' "Split did not show one pane per variant"
json_check "$STATE" 'len(set((round(p[0]), round(p[1])) for p in d["view"]["panes"])) == 6' "the six panes overlap"

click_widget "$STATE" view.panes
wait_for_state "$STATE" '"view.pane.2" in d["widgets"]' "the panes menu did not open"
click_widget "$STATE" view.pane.2
wait_for_state "$STATE" 'd["view"]["pane_variants"] == [0, 1, 3, 4, 5]' "unticking variant 2 did not take its pane away"
quit_app
echo "OK"

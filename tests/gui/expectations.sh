#!/usr/bin/env bash
# The GUI shows a preset's expected values beside the live measurements: friction_slide.json
# expects the slide to stop after 2.72 m at 1.36 s; before the stop the rest time is "not yet",
# once it rests both are measured and within their tolerance (the state dump's "expectations",
# the same list `compare --json` prints), and the rows are drawn under the description.
# Usage: expectations.sh <particle-lab binary> <source dir>
APP=$1
SRC=$2
source "$SRC/tests/gui/gui_test_lib.bash"
make_workdir
STATE="$WORK/state.json"

start_app "$SRC/presets/friction_slide.json" --frames 1000000 --dump-state "$STATE"
wait_for_state "$STATE" "d['t'] > 0.1 and len(d['expectations']) == 2" "the preset's two expectations are not listed"
json_check "$STATE" "d['t'] > 1.36 or d['expectations'][1]['measured'] is None" "a rest time was measured before the ball stopped"
wait_for_state "$STATE" "d['t'] > 1.5" "the simulation does not run"
dump_now "$STATE"
json_check "$STATE" "[e['quantity'] for e in d['expectations']] == ['final_range_m', 'time_to_rest_s']" "wrong quantities"
json_check "$STATE" "all(e['met'] and e['measured'] is not None for e in d['expectations'])" "the expectations are not met"
json_check "$STATE" "'expect.row0' in d['widgets'] and 'expect.row1' in d['widgets']" "the expectation rows are not drawn"
quit_app
echo "OK"

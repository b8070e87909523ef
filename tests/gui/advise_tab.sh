#!/usr/bin/env bash
# The Advise tab runs `particle-lab advise`'s code on the open scene in the background and shows
# its verdicts: on feather_vs_ball, a vertical drop, drag matters in the air variant by landing
# time (not by landing point or apex, which do not move), and so do buoyancy (the foam ball is 0.64
# of the air's density) and added mass; in the vacuum variant drag would change nothing; the two
# balls (mean free path 14 km) need no collisions.
# Usage: advise_tab.sh <particle-lab binary> <source dir>
APP=$1
SRC=$2
source "$SRC/tests/gui/gui_test_lib.bash"
make_workdir
STATE="$WORK/state.json"

start_app "$SRC/presets/feather_vs_ball.json" --frames 1000000 --dump-state "$STATE"
wait_for_state "$STATE" '"tab.advise" in d["widgets"]' "there is no Advise tab"
click_widget "$STATE" tab.advise
wait_for_state "$STATE" '"advise.run" in d["widgets"]' "the Advise tab did not open"
click_widget "$STATE" advise.run
wait_for_state "$STATE" 'len(d["advice"]["variants"]) == 2 and not d["advice"]["running"]' "the advice did not run to its end"
json_check "$STATE" 'any(v.startswith("drag matters: landing time +") for v in d["advice"]["variants"][0]["verdicts"])' \
    "the air variant's verdicts do not say drag matters by landing time"
json_check "$STATE" 'any(v.startswith("drag is off and would change nothing beyond tolerance") for v in d["advice"]["variants"][1]["verdicts"])' \
    "the vacuum variant's verdicts do not say that drag would change nothing"
json_check "$STATE" '"buoyancy" in d["advice"]["variants"][0]["matters"] and "added mass" in d["advice"]["variants"][0]["matters"]' \
    "buoyancy and added mass are not among the terms that matter"
json_check "$STATE" 'any(v.startswith("collisions do not matter: ") for v in d["advice"]["variants"][0]["verdicts"]) and not d["advice"]["variants"][0]["collisions_recommended"]' \
    "the collisions row does not say that the feather and the ball need no collisions"
quit_app
echo "OK"

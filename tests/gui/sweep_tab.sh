#!/usr/bin/env bash
# The Sweep tab runs a study over the current scene in the background: elevation 10:80:15 (its
# default) by drag.model none,linear,quadratic,sphere_re is 60 points, and the range at the
# first impact peaks at 45 degrees without drag (v^2 sin(2 theta) / g), lower with drag. A
# click on a point pins that point's run beside the live one, which stays as it was.
# Usage: sweep_tab.sh <particle-lab binary> <source dir>
APP=$1
SRC=$2
source "$SRC/tests/gui/gui_test_lib.bash"
make_workdir
STATE="$WORK/state.json"

start_app "$SRC/presets/optimal_angle.json" --frames 1000000 --dump-state "$STATE"
wait_for_state "$STATE" '"tab.sweep" in d["widgets"]' "there is no Sweep tab"
click_widget "$STATE" tab.sweep
wait_for_state "$STATE" '"sweep.two_axes" in d["widgets"]' "the Sweep tab did not open"
click_widget "$STATE" sweep.two_axes
click_widget "$STATE" sweep.run
wait_for_state "$STATE" 'd["sweep"]["points"] == 60 and not d["sweep"]["running"]' "the sweep did not run to its end"
json_check "$STATE" 'd["sweep"]["done"] == 60' "not every point of the sweep ran"
json_check "$STATE" 'len(d["sweep"]["best"]) == 4' "the line plot does not have one series per drag model"
json_check "$STATE" '{b["series"]: b["x"] for b in d["sweep"]["best"]}["drag.model=none"] == 45' \
    "without drag the longest range is not at 45 degrees"
json_check "$STATE" '{b["series"]: b["x"] for b in d["sweep"]["best"]}["drag.model=quadratic"] < 45' \
    "with quadratic drag the longest range is not below 45 degrees"
# The first series (drag.model=none) peaks at 45 degrees: click that point.
wait_for_state "$STATE" '"sweep.best0" in d["widgets"]' "the sweep plot does not say where its best point is"
click_widget "$STATE" sweep.best0
wait_for_state "$STATE" 'len(d["pinned_runs"]) == 1' "a click on a sweep point did not pin its run"
json_check "$STATE" '"launch.elevation_deg=45" in d["pinned_runs"][0]["label"] and "drag.model=none" in d["pinned_runs"][0]["label"]' \
    "the pinned run is not the clicked point (45 degrees, no drag)"
json_check "$STATE" 'not d["dirty"]' "pinning a sweep point changed the live scene"
quit_app
echo "OK"

#!/usr/bin/env bash
# The Stability tab computes the current method's dt x k map and, after it, the collision slice
# (pairs thrown at each other: physics/studies/collision_stability.cpp); its "collisions" view
# lists the cells that ended deep in each other or through each other, each warned by the engine.
# Usage: stability_tab.sh <particle-lab binary> <source dir>   (STABILITY_TAB_KEEP=FILE keeps a screenshot)
APP=$1
SRC=$2
source "$SRC/tests/gui/gui_test_lib.bash"
make_workdir
STATE="$WORK/state.json"

start_app "$SRC/presets/default.json" --frames 1000000 --dump-state "$STATE" --screenshot "$WORK/shot.png"
wait_for_state "$STATE" '"tab.stability" in d["widgets"]' "there is no Stability tab"
click_widget "$STATE" tab.stability
wait_for_state "$STATE" '"stability.compute" in d["widgets"]' "the Stability tab did not open"
click_widget "$STATE" stability.compute
for _ in $(seq 240); do
    dump_now "$STATE"
    json_get "$STATE" '"pair_outcomes" in d["stability"] and not d["stability"]["running"]' | grep -q True && break
    sleep 0.5
done
json_check "$STATE" '"pair_outcomes" in d["stability"] and not d["stability"]["running"]' "the map and the collision slice did not finish"
json_check "$STATE" 'd["stability"]["method"] == "semi_implicit_euler" and d["stability"]["map_cells"] > 0' "no map of the scene's method"
json_check "$STATE" 'sum(d["stability"]["pair_outcomes"].values()) == 216' "the collision slice is not 216 cells"
json_check "$STATE" 'd["stability"]["pair_outcomes"].get("stable", 0) > 150' "too few stable pairs"
json_check "$STATE" 'd["stability"]["pair_unstable"] > 0 and d["stability"]["pair_unstable_warned"] == d["stability"]["pair_unstable"] - d["stability"]["pair_outcomes"].get("energy_growth", 0)' \
    "a deep or crossed pair was not warned"
click_widget "$STATE" stability.collisions
wait_for_state "$STATE" 'd["stability"]["view"] == 2' "the collisions view did not open"
quit_app
[ -z "${STABILITY_TAB_KEEP:-}" ] || cp "$WORK/shot.png" "$STABILITY_TAB_KEEP"
echo "OK"

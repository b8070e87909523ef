#!/usr/bin/env bash
# Calm warnings: every shipped preset runs 15 simulated seconds without a warning that puts a
# number at risk (out-of-range drag whose error is negligible is only a note), except
# drag_models.json, whose lesson is the warning: Stokes drag on a ball far outside its Reynolds
# range (its description says so), and only that variant warns, and integrators.json, whose
# explicit-Euler variant at dt = 0.01 s can never come to rest (its description says so). The
# piles of thousands of colliding balls (granular_pile, poured_balls) run 1 s, through their
# fall and first impacts: 15 s of them would take minutes.
# Usage: calm_warnings.sh <particle-lab binary> <source dir>
APP=$1
SRC=$2
source "$SRC/tests/gui/gui_test_lib.bash"
make_workdir
STATE="$WORK/state.json"

for preset in "$SRC"/presets/*.json; do
    name=$(basename "$preset" .json)
    frames=30
    case "$name" in granular_pile | poured_balls) frames=2 ;; esac
    "$APP" "$preset" --frames "$frames" --fixed-frame-dt 0.5 --dump-state "$STATE" >"$WORK/app.out" 2>"$WORK/app.err" ||
        fail "$name: the app failed: $(cat "$WORK/app.err")"
    json_check "$STATE" "d[\"t\"] > $frames * 0.5 - 0.1" "$name did not run $frames half-seconds"
    if [ "$name" = drag_models ]; then
        json_check "$STATE" 'd["warning_count"] == 1 and d["warnings"][0]["variant"] == 1' \
            "drag_models: the Stokes variant should be the one warning"
        json_check "$preset" '"Warnings tab" in d["description"]' "drag_models: the description does not say its lesson is the warning"
    elif [ "$name" = integrators ]; then
        json_check "$STATE" 'd["warning_count"] == 1 and d["warnings"][0]["variant"] == 0' \
            "integrators: the explicit Euler variant should be the one warning"
        json_check "$preset" '"never comes to rest" in d["description"]' "integrators: the description does not say why it warns"
    else
        json_check "$STATE" 'd["warning_count"] == 0' "$name opens with a warning"
    fi
done
echo "OK"

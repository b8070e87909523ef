#!/usr/bin/env bash
# Pinned runs survive edits, relaunches and resets: P pins the run, an edit of dt starts a new
# live run beside it, P pins that one too (labelled by what differs: "dt 0.004 s"), and R, L and
# a second edit leave both pins in place, each with its own metrics and ghost path.
# Usage: pinned_runs.sh <particle-lab binary> <source dir>
APP=$1
SRC=$2
source "$SRC/tests/gui/gui_test_lib.bash"
make_workdir
STATE="$WORK/state.json"

set_dt() {
    click_widget "$STATE" time.dt
    wait_for_state "$STATE" 'd["text_input"]' "a click on the dt field did not put the keyboard in it"
    xdotool key ctrl+a
    xdotool type --delay 4 "$1"
    hold_key Return
}

start_app "$SRC/presets/default.json" --frames 1000000 --dump-state "$STATE"
wait_for_state "$STATE" 'd["t"] > 2.0 and "time.dt" in d["widgets"]' "the default preset does not run"
press p
wait_for_state "$STATE" 'len(d["pinned_runs"]) == 1' "P did not pin the run"
json_check "$STATE" 'd["pinned_runs"][0]["label"].startswith("run 1: ") and d["pinned_runs"][0]["metrics"]["time_of_flight_s"] is not None' \
    "the first pin has no label or no metrics"
json_check "$STATE" 'max(d["pinned_runs"][0]["path_samples"]) > 100' "the first pin has no path for its ghost"

set_dt 0.004
wait_for_state "$STATE" 'd["dirty"] and len(d["pinned_runs"]) == 1 and d["t"] < 1.0' "editing dt did not start a new run beside the pin"
wait_for_state "$STATE" 'd["t"] > 2.0' "the edited run does not run"
press p
wait_for_state "$STATE" 'len(d["pinned_runs"]) == 2' "P did not pin the second run"
json_check "$STATE" '"dt 0.004 s" in d["pinned_runs"][1]["label"]' "the second pin is not labelled by what differs"

press r
press l
set_dt 0.001
wait_for_state "$STATE" 'd["t"] > 0.5' "the run after the second edit does not run"
json_check "$STATE" '[p["number"] for p in d["pinned_runs"]] == [1, 2]' "R, L or an edit wiped the pins"
# The scene has unsaved edits (Ctrl+Q would ask): end it the way a session manager does.
kill -TERM "$APP_PID"
wait_exit
echo "OK"

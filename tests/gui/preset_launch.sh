#!/usr/bin/env bash
# A preset is an experiment: its particle 0's velocity is the Launch panel's, so L throws what
# the preset throws. altitude_air.json's baseball leaves at (25, 10, 0) m/s, not at the
# default preset's (3, 4, 1); opening another preset brings its own launch.
# Usage: preset_launch.sh <particle-lab binary> <source dir>
APP=$1
SRC=$2
source "$SRC/tests/gui/gui_test_lib.bash"
make_workdir
STATE="$WORK/state.json"

start_app "$SRC/presets/default.json" --frames 1000000 --dump-state "$STATE"
wait_for_state "$STATE" 'd["launch_velocity"] == [3.0, 4.0, 1.0]' "the default preset's launch is not its particle 0's"
open_by_path "$SRC/presets/altitude_air.json" "$STATE"
wait_for_state "$STATE" 'd["preset"].endswith("altitude_air.json")' "Ctrl+O did not open altitude_air.json"
json_check "$STATE" 'd["launch_velocity"] == [25.0, 10.0, 0.0]' "the Launch panel kept the previous preset's velocity"

wait_for_state "$STATE" 'd["t"] > 1.0' "altitude_air.json does not run"
press space
wait_for_state "$STATE" 'd["paused"]' "space did not pause"
press l
wait_for_state "$STATE" 'all(v["particles"][0]["velocity"] == [25.0, 10.0, 0.0] for v in d["variants"])' \
    "L did not throw the preset's baseball at its own velocity"
quit_app
echo "OK"

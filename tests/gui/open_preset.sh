#!/usr/bin/env bash
# Loading another shipped preset through the GUI with the keyboard (Ctrl+O, type its path,
# Enter): the session now holds that preset (path, name, variants, particles), is not dirty,
# starts from t = 0 and runs; no error is shown.
# Usage: open_preset.sh <particle-lab binary> <source dir>
APP=$1
SRC=$2
source "$SRC/tests/gui/gui_test_lib.bash"
make_workdir
STATE="$WORK/state.json"
TARGET="$SRC/presets/launch_velocities.json"

start_app "$SRC/presets/default.json" --frames 1000000 --dump-state "$STATE"
wait_for_state "$STATE" 'd["t"] > 0.3 and d["preset"].endswith("default.json")' "the default preset does not run"

open_by_path "$TARGET" "$STATE"
wait_for_state "$STATE" "d['preset'] == '$TARGET'" "typing the path and Enter did not load $TARGET"
"$PYTHON" - "$STATE" "$TARGET" <<'PY' || fail "the loaded scene is not the preset ($(head -c 600 "$STATE"))"
import json, math, sys
d, preset = json.load(open(sys.argv[1])), json.load(open(sys.argv[2]))
assert d["scene_name"] == preset["name"], (d["scene_name"], preset["name"])
assert len(d["variants"]) == max(1, len(preset.get("variants", []))), len(d["variants"])
want = len(preset["particles"])
assert all(len(v["particles"]) == want for v in d["variants"]), [len(v["particles"]) for v in d["variants"]]
# The particles started where the file puts them: no farther away than the launch speed and
# free fall (drag only slows them) take them in the time run since the load.
t = d["t"]
for got, spec in zip(d["variants"][0]["particles"], preset["particles"]):
    g = math.hypot(*preset.get("world", {}).get("gravity", [0, -9.81, 0]))
    reach = math.hypot(*spec["velocity"]) * t + 0.5 * g * t * t + 1e-6
    assert math.dist(got["position"], spec["position"]) <= reach, (got, spec, t)
assert not d["dirty"] and d["error_popup"] == "", d
assert d["t"] < 0.3, "the loaded preset did not start from t = 0"
assert not d["text_input"], "Enter left the keyboard in the path field"
PY
t_loaded=$(json_get "$STATE" 'd["t"]')
wait_for_state "$STATE" "d['t'] > $t_loaded + 0.2" "the loaded preset does not run"

quit_app
echo "OK"

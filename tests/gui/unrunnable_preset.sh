#!/usr/bin/env bash
# A preset that validates but cannot run here (an emitter of 2e6 particles x 1000 variants,
# about 390 GB of state) opened with Ctrl+O: a dialog gives the numbers, the app stays up, and
# the scene it had (with its unsaved edit, after Discard) is kept and still runs.
# Usage: unrunnable_preset.sh <particle-lab binary> <source dir>
APP=$1
SRC=$2
source "$SRC/tests/gui/gui_test_lib.bash"
make_workdir
STATE="$WORK/state.json"
BIG="$WORK/big.json"
"$PYTHON" "$SRC/tests/hostile/gen.py" big 2000000 >"$BIG"
"$APP" validate "$BIG" >/dev/null || fail "the generated preset does not validate"

start_app "$SRC/presets/default.json" --frames 1000000 --dump-state "$STATE"
wait_for_state "$STATE" 'd["t"] > 0.2 and d["preset"].endswith("default.json")' "the default preset does not run"

# Without unsaved edits Ctrl+O loads at once: the refusal, with the numbers.
open_by_path "$BIG" "$STATE"
wait_for_state "$STATE" 'd["error_popup"] != ""' "opening $BIG showed no error"
json_check "$STATE" '__import__("re").search(r"needs about [0-9.]+ GB of memory \(2000000 particles x 1000 variants x [0-9]+ bytes\), but the machine has [0-9.]+ GB available", d["error_popup"]) and "current scene is kept" in d["error_popup"]' \
    "the dialog does not give the numbers"
kill -0 "$APP_PID" 2>/dev/null || fail "the app ended; stderr: $(cat "$WORK/app.err")"
json_check "$STATE" 'd["preset"].endswith("default.json") and len(d["variants"]) == 1 and len(d["variants"][0]["particles"]) == 1 and not d["dirty"]' \
    "the scene was not kept"
hold_key Return  # OK
wait_for_state "$STATE" 'd["error_popup"] == ""' "Enter did not close the error dialog"
t_kept=$(json_get "$STATE" 'd["t"]')
wait_for_state "$STATE" "d['t'] > $t_kept + 0.2" "the kept scene does not run"

quit_app
echo "OK"

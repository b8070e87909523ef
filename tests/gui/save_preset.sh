#!/usr/bin/env bash
# Ctrl+S saves the open preset in place through the GUI: the previous file is kept as .bak, the
# saved file validates and loads back to the same scene, and the session is no longer dirty.
# Usage: save_preset.sh <particle-lab binary> <source dir>
APP=$1
SRC=$2
source "$SRC/tests/gui/gui_test_lib.bash"
make_workdir
STATE="$WORK/state.json"
PRESET="$WORK/my_preset.json"
cp "$SRC/presets/default.json" "$PRESET"

start_app "$PRESET" --frames 1000000 --dump-state "$STATE"
wait_for_state "$STATE" 'd["t"] > 0.2' "the simulation does not run"

press ctrl+s
for _ in $(seq 100); do
    [ -f "$PRESET.bak" ] && break
    sleep 0.05
done
[ -f "$PRESET.bak" ] || fail "Ctrl+S did not save (no $PRESET.bak)"
cmp -s "$PRESET.bak" "$SRC/presets/default.json" || fail "the backup is not the previous file"
"$APP" validate "$PRESET" > /dev/null || fail "the saved preset does not validate"

# The saved file lists every field; the scene it describes is the one that was opened.
"$PYTHON" - "$PRESET" "$SRC/presets/default.json" <<'PY' || fail "the saved preset differs from the opened one"
import json, sys
saved, original = json.load(open(sys.argv[1])), json.load(open(sys.argv[2]))
def covers(big, small, path=""):
    if isinstance(small, dict):
        for k, v in small.items():
            assert k in big, path + "." + k
            covers(big[k], v, path + "." + k)
    elif isinstance(small, list):
        assert len(big) == len(small), path
        for i, (a, b) in enumerate(zip(big, small)):
            covers(a, b, f"{path}[{i}]")
    else:
        assert big == small, (path, big, small)
covers(saved, original)
PY

dump_now "$STATE"
json_check "$STATE" 'not d["dirty"]' "the session is still marked dirty after saving"
quit_app
echo "OK"

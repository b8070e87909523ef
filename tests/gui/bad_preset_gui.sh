#!/usr/bin/env bash
# A preset that does not load, opened inside the GUI (Ctrl+O, path, Enter): the error dialog
# names the field and the rule, the open scene is kept (same file, name, particles) and keeps
# running; Enter (or Esc) dismisses the dialog and the lab works on. The last frame, with the
# dialog up, is written as a screenshot.
# Usage: bad_preset_gui.sh <particle-lab binary> <source dir>
APP=$1
SRC=$2
source "$SRC/tests/gui/gui_test_lib.bash"
make_workdir
STATE="$WORK/state.json"
SHOT="$WORK/error_dialog.png"
KEPT="$SRC/presets/restitution.json"
BAD="$WORK/negative_mass.json"
"$PYTHON" - "$SRC/presets/default.json" "$BAD" <<'PY'
import json, sys
preset = json.load(open(sys.argv[1]))
preset["particles"][0]["mass"] = -1
json.dump(preset, open(sys.argv[2], "w"), indent=2)
PY

start_app "$KEPT" --frames 1000000 --dump-state "$STATE" --screenshot "$SHOT"
wait_for_state "$STATE" 'd["t"] > 0.2' "the preset does not run"
kept_scene() { json_get "$STATE" '(d["preset"], d["scene_name"], [len(v["particles"]) for v in d["variants"]], d["dirty"])'; }
before=$(kept_scene)

# 1. Negative mass: the dialog says which field and why; the scene stays and runs on.
open_by_path "$BAD" "$STATE"
wait_for_state "$STATE" '"particles[0].mass: must be >= 1e-15, got -1" in d["error_popup"]' \
    "no error dialog naming particles[0].mass"
json_check "$STATE" "\"$BAD\" in d['error_popup'] and 'current scene is kept' in d['error_popup']" \
    "the dialog does not name the file or say the scene is kept"
[ "$(kept_scene)" = "$before" ] || fail "the failed load changed the scene: $(kept_scene) (was $before)"
t_error=$(json_get "$STATE" 'd["t"]')
wait_for_state "$STATE" "d['t'] > $t_error + 0.2 and d['error_popup'] != ''" "the scene stopped behind the dialog"

# Enter dismisses it; the lab still answers keys and still holds the kept scene.
hold_key Return
wait_for_state "$STATE" 'd["error_popup"] == ""' "Enter did not dismiss the error dialog"
press space
wait_for_state "$STATE" 'd["paused"]' "space does nothing after the dialog"
press space
wait_for_state "$STATE" 'not d["paused"]' "space does nothing after the dialog"
[ "$(kept_scene)" = "$before" ] || fail "the scene changed after dismissing the dialog: $(kept_scene)"

# 2. A file that is not there: Esc dismisses that dialog.
open_by_path "$WORK/no_such_preset.json" "$STATE"
wait_for_state "$STATE" '"no_such_preset.json" in d["error_popup"]' "no error dialog for a missing file"
press Escape
wait_for_state "$STATE" 'd["error_popup"] == ""' "Esc did not dismiss the error dialog"

# 3. The bad preset again, and quit with the dialog up: the screenshot shows it.
open_by_path "$BAD" "$STATE"
wait_for_state "$STATE" '"particles[0].mass" in d["error_popup"]' "no error dialog the second time"
[ "$(kept_scene)" = "$before" ] || fail "the scene changed: $(kept_scene)"
quit_app
[ -s "$SHOT" ] || fail "no screenshot written"
# Not blank where the dialog sits (its words are checked above through the state dump; the PNG
# is for a person to judge, kept with PL_KEEP_SCREENSHOT=<file>).
png_stats "$SHOT" 0.38,0.42,0.62,0.56 >"$WORK/stats.txt"
{ read -r width height; read -r sd colours; } <"$WORK/stats.txt"
"$PYTHON" -c "import sys; sys.exit(0 if $sd > 10 and $colours > 20 else 1)" ||
    fail "the middle of the screenshot looks empty (brightness sd $sd, $colours colours)"
if [ -n "${PL_KEEP_SCREENSHOT:-}" ]; then cp "$SHOT" "$PL_KEEP_SCREENSHOT"; fi
echo "OK"

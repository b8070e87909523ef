#!/usr/bin/env bash
# Shipped presets are read-only and overwriting asks first. The app runs from a copy of the
# binary beside a copied share/particle-lab (so a broken build cannot write into the source
# tree). Ctrl+S on a shipped preset opens the file dialog in the user's preset folder; Enter
# saves the copy there and the shipped file stays byte-identical. After an edit, Save as... onto
# that copy asks Overwrite / Cancel: Cancel keeps the file, Overwrite replaces it. Ctrl+Q with an
# unsaved edit of a shipped preset and "Save and quit" saves a copy under a typed name first.
# Usage: shipped_preset_save.sh <particle-lab binary> <source dir>
APP=$1
SRC=$2
source "$SRC/tests/gui/gui_test_lib.bash"
make_workdir
STATE="$WORK/state.json"
mkdir -p "$WORK/bin" "$WORK/share/particle-lab"
cp "$APP" "$WORK/bin/particle-lab"
cp -r "$SRC/presets" "$SRC/shaders" "$WORK/share/particle-lab/"
APP="$WORK/bin/particle-lab"
SHIPPED="$WORK/share/particle-lab/presets/default.json"
USER_DIR="$XDG_DATA_HOME/particle-lab/presets"
EDITED_DT=0.004

# Enter in the dialog's filename field until `condition` holds: a frame slower than hold_key's
# 0.12 s (a loaded machine) misses the key, as Dear ImGui 1.86 sees only keys down at a frame's
# start; a missed Enter changes nothing, so pressing again is safe.
enter_until() {
    local condition=$1 message=$2
    press_until Return 3 "$condition" && return 0
    fail "$message (condition: $condition; state: $(head -c 400 "$STATE"))"
}

# Waits for the save dialog with the keyboard in its filename field.
wait_save_dialog() {
    wait_for_state "$STATE" "d['file_dialog'] is not None and d['file_dialog']['mode'] == 'save' and d['text_input']" \
        "$1 did not open the save dialog"
}

start_app "$SHIPPED" --frames 1000000 --dump-state "$STATE"
wait_for_state "$STATE" "d['t'] > 0.2 and 'time.dt' in d['widgets'] and 'preset.save_as' in d['widgets']" \
    "the shipped default preset does not run"

# Ctrl+S on the shipped preset: Save As into the user's folder, the name filled in.
press ctrl+s
wait_save_dialog "Ctrl+S on a shipped preset"
json_check "$STATE" "d['file_dialog']['dir'] == '$USER_DIR' and d['file_dialog']['filename'] == 'default.json'" \
    "the save dialog is not in the user's preset folder with the preset's name"
enter_until "d['file_dialog'] is None and d['preset'] == '$USER_DIR/default.json' and not d['dirty']" \
    "Enter in the save dialog did not save the user copy"
cmp -s "$SHIPPED" "$SRC/presets/default.json" || fail "the shipped preset changed"
[ ! -e "$SHIPPED.bak" ] || fail "a backup was written beside the shipped preset"
"$APP" validate "$USER_DIR/default.json" >/dev/null || fail "the user copy does not validate"
cp "$USER_DIR/default.json" "$WORK/copy_before.json"

# Save as... onto the existing copy after an edit: the overwrite question; Cancel keeps the file.
edit_dt
click_widget "$STATE" preset.save_as
wait_save_dialog "Save as..."
enter_until "d['file_dialog'] is not None and d['file_dialog']['overwrite'] == '$USER_DIR/default.json' and 'file_dialog.keep' in d['widgets']" \
    "saving onto an existing file did not ask first"
sleep 0.3  # the dialog settles its size on its first frames
dump_now "$STATE"
click_widget "$STATE" file_dialog.keep
wait_for_state "$STATE" "d['file_dialog'] is not None and d['file_dialog']['overwrite'] is None" "Cancel did not go back to the dialog"
press_until Escape 3 "d['file_dialog'] is None" || true  # the wait below says what went wrong
wait_for_state "$STATE" "d['file_dialog'] is None and d['dirty']" "Esc did not close the dialog (or the edit was lost)"
cmp -s "$USER_DIR/default.json" "$WORK/copy_before.json" || fail "Cancel on the overwrite question changed the file"

# Overwrite replaces it.
click_widget "$STATE" preset.save_as
wait_save_dialog "Save as... (again)"
enter_until "d['file_dialog'] is not None and d['file_dialog']['overwrite'] is not None and 'file_dialog.overwrite' in d['widgets']" \
    "the overwrite question did not come back"
sleep 0.3
dump_now "$STATE"
click_widget "$STATE" file_dialog.overwrite
wait_for_state "$STATE" "d['file_dialog'] is None and not d['dirty']" "Overwrite did not save"
[ "$(json_get "$USER_DIR/default.json" 'd["integrator"]["dt"]')" = "$EDITED_DT" ] || fail "Overwrite did not write the edit"

# A shipped preset, an edit, Ctrl+Q, "Save and quit": a copy under a typed name, then the app exits.
open_by_path "$WORK/share/particle-lab/presets/drag_models.json" "$STATE"
wait_for_state "$STATE" "d['preset'].endswith('/drag_models.json') and not d['dirty']" "the shipped drag_models preset did not open"
edit_dt
press ctrl+q
wait_for_state "$STATE" "d['pending'] == 'quit' and 'unsaved.save' in d['widgets']" "Ctrl+Q did not ask about the edit"
sleep 0.3
dump_now "$STATE"
click_widget "$STATE" unsaved.save
wait_save_dialog '"Save and quit" on a shipped preset'
xdotool key ctrl+a
xdotool type --delay 4 "my drag"
for _ in 1 2 3; do  # again if a slow frame missed the Enter (see enter_until)
    hold_key Return
    for _ in $(seq 40); do
        kill -0 "$APP_PID" 2>/dev/null || break 2
        sleep 0.05
    done
done
wait_exit
[ "$APP_EXIT_CODE" -eq 0 ] || fail "exit code $APP_EXIT_CODE after Save and quit"
[ "$(json_get "$USER_DIR/my drag.json" 'd["integrator"]["dt"]')" = "$EDITED_DT" ] || fail "Save and quit did not save the copy"
for f in default drag_models; do
    cmp -s "$WORK/share/particle-lab/presets/$f.json" "$SRC/presets/$f.json" || fail "the shipped $f preset changed"
done
echo "OK"

#!/usr/bin/env bash
# Plot exports ask before they overwrite: with particle-lab-plots.png already in the export
# folder (the working directory), the PNG button opens "Overwrite?"; Cancel keeps the file as it
# was, Overwrite replaces it with the picture of the plots.
# Usage: export_overwrite.sh <particle-lab binary> <source dir>
APP=$1
SRC=$2
source "$SRC/tests/gui/gui_test_lib.bash"
make_workdir
STATE="$WORK/state.json"
cd "$WORK"
TARGET="$WORK/particle-lab-plots.png"
echo "an older export" > "$TARGET"
cp "$TARGET" "$WORK/before"

start_app "$SRC/presets/default.json" --frames 1000000 --dump-state "$STATE"
wait_for_state "$STATE" "d['t'] > 0.2 and 'plots.png' in d['widgets']" "the plots are not shown"

answer() {
    click_widget "$STATE" plots.png
    wait_for_state "$STATE" "d['export_question'] and 'export.$1' in d['widgets']" "exporting onto an existing file did not ask first"
    sleep 0.3  # the dialog settles its size and place on its first frames
    dump_now "$STATE"
    click_widget "$STATE" "export.$1"
    wait_for_state "$STATE" "not d['export_question']" "$1 did not close the question"
}

answer cancel
sleep 0.5  # a picture wrongly taken would be written by now
cmp -s "$TARGET" "$WORK/before" || fail "Cancel overwrote the export"

answer overwrite
for _ in $(seq 100); do
    cmp -s "$TARGET" "$WORK/before" || break
    sleep 0.05
done
read -r w h < <(png_stats "$TARGET" | head -n 1) || fail "Overwrite did not write a PNG"
[ "$w" -gt 100 ] && [ "$h" -gt 100 ] || fail "the exported picture is only ${w}x$h"
quit_app
echo "OK"

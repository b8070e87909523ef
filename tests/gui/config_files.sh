#!/usr/bin/env bash
# Hostile settings files never hang or blank the app: camera.txt or imgui.ini as a FIFO (opening
# one blocks until a writer comes), camera.txt as /dev/zero (endless), and a camera file with
# 3e38 values (a blank view) are ignored; start-up, 5 frames and exit finish in seconds.
# Usage: config_files.sh <particle-lab binary> <source dir>
APP=$1
SRC=$2
source "$SRC/tests/gui/gui_test_lib.bash"
make_workdir
config=$XDG_CONFIG_HOME/particle-lab

start_and_exit() {
    local what=$1 code=0
    timeout --kill-after=5 30 "$APP" --frames 5 --fixed-frame-dt 0.016 --dump-state "$WORK/state.json" 2>"$WORK/err.txt" || code=$?
    [ "$code" -ne 124 ] && [ "$code" -ne 137 ] || fail "$what: the app hung at start-up or exit"
    [ "$code" -eq 0 ] || fail "$what: exit code $code; stderr: $(cat "$WORK/err.txt")"
    echo "ok: $what"
}

mkdir -p "$config"
mkfifo "$config/camera.txt"
start_and_exit "camera.txt is a FIFO"
rm "$config/camera.txt"

rm -f "$config/imgui.ini"
mkfifo "$config/imgui.ini"
start_and_exit "imgui.ini is a FIFO"
[ -p "$config/imgui.ini" ] || fail "imgui.ini (a FIFO) was replaced"
rm "$config/imgui.ini"

ln -sfn /dev/zero "$config/camera.txt"
start_and_exit "camera.txt is /dev/zero"
rm "$config/camera.txt"

# The room of presets/default.json with absurd view values: the default framing is used instead.
start_and_exit "first start (writes camera.txt)"
room_line=$(grep '^room ' "$config/camera.txt")
printf 'target 3e38 3e38 3e38\norbit 3e38 1 3e38\n%s\n' "$room_line" >"$config/camera.txt"
start_and_exit "camera.txt holds 3e38"
json_check "$WORK/state.json" 'abs(d["view"]["camera"]["distance"]) < 1e6 and all(abs(v) < 1e6 for v in d["view"]["camera"]["target"])' \
    "the absurd camera values were used"

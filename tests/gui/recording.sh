#!/usr/bin/env bash
# Recording through ffmpeg on the fixed simulated clock: `--record` writes exactly seconds x fps
# frames with the right duration (ffprobe), two recordings of the same preset are the same
# frames, GIF and WebM work, a missing ffmpeg or a shipped target is a clear error, and F9 in
# the GUI starts and stops a recording whose frame count matches what the app reported.
# Usage: recording.sh <particle-lab binary> <source dir>
APP=$1
SRC=$2
source "$SRC/tests/gui/gui_test_lib.bash"
make_workdir
command -v ffprobe >/dev/null || fail "ffprobe is missing (Debian package ffmpeg, in ./lab's test packages)"
PRESET="$SRC/presets/default.json"

frame_count() {
    ffprobe -v error -count_frames -select_streams v:0 -show_entries stream=nb_read_frames -of default=nw=1:nk=1 "$1"
}
duration() {
    ffprobe -v error -show_entries format=duration -of default=nw=1:nk=1 "$1"
}
# The decoded frames' checksums (not the container's bytes, which may carry a timestamp).
frame_sums() {
    ffmpeg -v error -i "$1" -f framemd5 - | grep -v '^#'
}
record() {
    "$APP" "$PRESET" "$@" >"$WORK/rec.out" 2>"$WORK/rec.err" || fail "recording $* failed: $(cat "$WORK/rec.err")"
}

# 2 s at 30 fps of the 3D view, twice.
for run in 1 2; do
    record --record "$WORK/run$run.mp4" --record-seconds 2 --record-fps 30 --record-area view
    [ "$(frame_count "$WORK/run$run.mp4")" = 60 ] || fail "run $run: $(frame_count "$WORK/run$run.mp4") frames, expected 60"
    "$PYTHON" -c 'import sys; sys.exit(0 if abs(float(sys.argv[1]) - 2.0) < 0.02 else 1)' "$(duration "$WORK/run$run.mp4")" ||
        fail "run $run lasts $(duration "$WORK/run$run.mp4") s, expected 2"
done
[ "$(frame_sums "$WORK/run1.mp4")" = "$(frame_sums "$WORK/run2.mp4")" ] ||
    fail "two recordings of the same preset differ"
ls "$WORK" | grep -q '\.tmp\.' && fail "a temporary file was left beside the recordings: $(ls "$WORK")"

# The whole window as a GIF (1 s at 10 fps), the plots as WebM (0.5 s at 10 fps).
record --record "$WORK/window.gif" --record-seconds 1 --record-fps 10
[ "$(frame_count "$WORK/window.gif")" = 10 ] || fail "the GIF has $(frame_count "$WORK/window.gif") frames, expected 10"
record --record "$WORK/plots.webm" --record-seconds 0.5 --record-fps 10 --record-area plots
[ "$(frame_count "$WORK/plots.webm")" = 5 ] || fail "the WebM has $(frame_count "$WORK/plots.webm") frames, expected 5"

# Without ffmpeg on PATH: exit 1 with a message naming it, and no file.
mkdir "$WORK/no-ffmpeg"
status=0
PATH="$WORK/no-ffmpeg" "$APP" "$PRESET" --record "$WORK/none.mp4" --record-seconds 1 2>"$WORK/err.txt" || status=$?
[ "$status" = 1 ] || fail "without ffmpeg the exit code is $status, expected 1"
grep -q "ffmpeg" "$WORK/err.txt" || fail "the missing ffmpeg is not named: $(cat "$WORK/err.txt")"
[ ! -e "$WORK/none.mp4" ] || fail "a recording without ffmpeg left a file"
# A shipped folder or a non-video name is refused before any window opens.
status=0
"$APP" "$PRESET" --record "$SRC/presets/recording.mp4" --record-seconds 1 2>"$WORK/err.txt" || status=$?
[ "$status" = 2 ] && grep -q "shipped" "$WORK/err.txt" || fail "recording into presets/ was not refused: $(cat "$WORK/err.txt")"
status=0
"$APP" "$PRESET" --record "$WORK/out.txt" --record-seconds 1 2>"$WORK/err.txt" || status=$?
[ "$status" = 2 ] && grep -q -- "--record" "$WORK/err.txt" || fail "a non-video name was not refused: $(cat "$WORK/err.txt")"

# F9 in the GUI: start, let it run, stop; the file has the frames the app says it recorded.
export XDG_VIDEOS_DIR="$WORK/videos"
mkdir -p "$XDG_VIDEOS_DIR"
STATE="$WORK/state.json"
start_app "$PRESET" --frames 1000000 --dump-state "$STATE"
wait_for_state "$STATE" 'd["t"] > 0.2' "the default preset does not run"
press F9
wait_for_state "$STATE" 'd["recording"]["active"] and d["recording"]["frames"] >= 5' "F9 did not start a recording"
press F9
wait_for_state "$STATE" 'not d["recording"]["active"] and d["recording"]["last_file"]' "F9 did not stop the recording"
file=$(json_get "$STATE" 'd["recording"]["last_file"]')
frames=$(json_get "$STATE" 'd["status"].split()[1]')
[ "$(dirname "$file")" = "$XDG_VIDEOS_DIR" ] || fail "the recording went to $file, not \$XDG_VIDEOS_DIR"
[ "$(frame_count "$file")" = "$frames" ] || fail "the GUI recording has $(frame_count "$file") frames, the app reported $frames"
quit_app
echo "OK"

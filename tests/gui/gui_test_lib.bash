# Helpers shared by the GUI tests (sourced; not a test itself: CTest runs tests/gui/*.sh).
# Every test runs under its own X display (tests/gui/with_display.sh) and its own config dir.

set -euo pipefail

# Debian's interpreter when present: a version-manager shim first on PATH can take a second or
# more per start, and the tests start Python often.
if [ -x /usr/bin/python3 ]; then PYTHON=/usr/bin/python3; else PYTHON=python3; fi

fail() {
    echo "FAIL: $*" >&2
    exit 1
}

# A scratch directory removed at exit; XDG_CONFIG_HOME and XDG_DATA_HOME (the user's presets)
# inside it so no user settings leak in and nothing is written into the user's folders.
make_workdir() {
    WORK=$(mktemp -d)
    export XDG_CONFIG_HOME="$WORK/config"
    export XDG_DATA_HOME="$WORK/data"
    APP_PID=""
    trap 'cleanup_app; rm -rf "$WORK"' EXIT
}

cleanup_app() {
    if [ -n "${APP_PID:-}" ] && kill -0 "$APP_PID" 2>/dev/null; then
        kill -TERM "$APP_PID" 2>/dev/null || true
        wait "$APP_PID" 2>/dev/null || true
    fi
}

# Reads a value from a JSON file with a Python expression over `d`, e.g. json_get f 'd["t"]'.
json_get() {
    "$PYTHON" -c 'import json, sys; d = json.load(open(sys.argv[1])); print(eval(sys.argv[2]))' "$1" "$2"
}

# Checks a Python condition over the JSON file `d`; fails with `message` otherwise.
json_check() {
    local file=$1 condition=$2 message=$3
    "$PYTHON" -c 'import json, sys; d = json.load(open(sys.argv[1])); sys.exit(0 if eval(sys.argv[2]) else 1)' \
        "$file" "$condition" || fail "$message (condition: $condition; state: $(head -c 400 "$file"))"
}

# Prints "width height" of a PNG on the first line, then "stddev distinct_colours" of the
# brightness for each region given as fractions of the image "x0,y0,x1,y1" (default: all of it).
# Decoded by stb_image (libstb, linked by the app too) in a small C program built on first use:
# decoding a 1600x900 PNG in pure Python takes seconds.
png_stats() {
    if [ ! -x "$WORK/png_stats" ]; then
        cc -O2 -std=c11 -I/usr/include/stb -o "$WORK/png_stats" -x c - -lstb -lm <<'C' || fail "cannot build the PNG checker"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <stb_image.h>
int main(int argc, char** argv) {
    int w, h, n;
    unsigned char* px = stbi_load(argv[1], &w, &h, &n, 3);
    if (!px) { fprintf(stderr, "cannot decode %s\n", argv[1]); return 1; }
    printf("%d %d\n", w, h);
    const char* whole = "0,0,1,1";
    const int regions = argc > 2 ? argc - 2 : 1;
    for (int r = 0; r < regions; ++r) {
        double f[4];
        if (sscanf(argc > 2 ? argv[2 + r] : whole, "%lf,%lf,%lf,%lf", &f[0], &f[1], &f[2], &f[3]) != 4) return 2;
        int x0 = (int)(f[0] * w), y0 = (int)(f[1] * h), x1 = (int)(f[2] * w), y1 = (int)(f[3] * h);
        double sum = 0, sum2 = 0, count = 0;
        static unsigned char seen[1 << 21];  /* 7 bits per channel */
        for (int i = 0; i < (1 << 21); ++i) seen[i] = 0;
        long colours = 0;
        for (int y = y0; y < y1; ++y)
            for (int x = x0; x < x1; ++x) {
                const unsigned char* p = px + 3 * ((long)y * w + x);
                double v = (p[0] + p[1] + p[2]) / 3.0;
                sum += v; sum2 += v * v; count += 1;
                int key = (p[0] >> 1) << 14 | (p[1] >> 1) << 7 | (p[2] >> 1);
                if (!seen[key]) { seen[key] = 1; ++colours; }
            }
        double mean = sum / count;
        printf("%.2f %ld\n", sqrt(fmax(sum2 / count - mean * mean, 0.0)), colours);
    }
    stbi_image_free(px);
    return 0;
}
C
    fi
    "$WORK/png_stats" "$@"
}

# Starts the app in the background (APP_PID) and waits for its window (APP_WINDOW).
start_app() {
    "$APP" "$@" >"$WORK/app.out" 2>"$WORK/app.err" &
    APP_PID=$!
    APP_WINDOW=$(timeout 30 xdotool search --sync --onlyvisible --name '^particle-lab' | head -n 1) ||
        fail "no particle-lab window appeared; stderr: $(cat "$WORK/app.err")"
    xdotool windowfocus --sync "$APP_WINDOW"
}

# Real key events (XTEST) to the focused app window.
press() {
    xdotool windowfocus --sync "$APP_WINDOW"
    xdotool key "$@"
}

# Asks the running app for a state dump (SIGUSR1) and waits until it is written.
dump_now() {
    local file=$1
    rm -f "$file"
    kill -USR1 "$APP_PID"
    for _ in $(seq 100); do
        [ -s "$file" ] && return 0
        sleep 0.05
    done
    fail "no state dump appeared at $file"
}

# Dumps until the condition holds (the app needs a frame or two to act on a key).
wait_for_state() {
    local file=$1 condition=$2 message=$3
    for _ in $(seq 60); do
        dump_now "$file"
        "$PYTHON" -c 'import json, sys; d = json.load(open(sys.argv[1])); sys.exit(0 if eval(sys.argv[2]) else 1)' \
            "$file" "$condition" && return 0
        sleep 0.05
    done
    fail "$message (condition: $condition; state: $(head -c 400 "$file"))"
}

# Waits for the app to exit; sets APP_EXIT_CODE.
wait_exit() {
    for _ in $(seq 200); do
        kill -0 "$APP_PID" 2>/dev/null || break
        sleep 0.05
    done
    kill -0 "$APP_PID" 2>/dev/null && fail "the app did not exit"
    APP_EXIT_CODE=0
    wait "$APP_PID" || APP_EXIT_CODE=$?
    APP_PID=""
}

# Holds a key down for a moment: ImGui 1.86 widgets (Enter in a text field, a dialog's Enter)
# see a key only if it is still down when a frame starts; `press` may be too quick for them.
hold_key() {
    xdotool windowfocus --sync "$APP_WINDOW"
    xdotool keydown "$1"
    sleep 0.12
    xdotool keyup "$1"
}

# Opens a preset the way a user types it: Ctrl+O puts the keyboard in the preset panel's path
# field (its old text selected), then the path and Enter. `state` is the --dump-state file.
open_by_path() {
    local path=$1 state=$2
    press ctrl+o
    wait_for_state "$state" 'd["text_input"]' "Ctrl+O did not put the keyboard in the open field"
    xdotool type --delay 4 "$path"
    hold_key Return
}

# Quits with Ctrl+Q and fails unless the app exits with status 0.
quit_app() {
    press ctrl+q
    wait_exit
    [ "$APP_EXIT_CODE" -eq 0 ] || fail "exit code $APP_EXIT_CODE after Ctrl+Q; stderr: $(cat "$WORK/app.err")"
}

# Prints "x y", the centre of a widget the app listed in the state dump's "widgets" (see
# ui::note_item_rect), from the dump file `state`.
widget_center() {
    local state=$1 name=$2
    json_get "$state" "' '.join(str(round(d['widgets']['$name'][k] + d['widgets']['$name'][k + 2] / 2)) for k in (0, 1))"
}

# Clicks the centre of a widget the app listed in the state dump `state` (see widget_center).
click_widget() {
    local state=$1 name=$2 x y
    read -r x y < <(widget_center "$state" "$name")
    xdotool mousemove --window "$APP_WINDOW" "$x" "$y" click 1
}

# An edit as a user makes it: a new dt typed into the Time section's field (clicked through the
# state dump $STATE); waits until the scene is dirty with dt = $EDITED_DT.
edit_dt() {
    click_widget "$STATE" time.dt
    wait_for_state "$STATE" 'd["text_input"]' "a click on the dt field did not put the keyboard in it"
    xdotool key ctrl+a
    xdotool type --delay 4 "$EDITED_DT"
    # Enter again if a frame slower than hold_key's 0.12 s missed it (a loaded machine); once
    # applied, the keyboard has left the field and another Enter does nothing.
    local applied="d['dirty'] and d['scene_dt'] == $EDITED_DT and not d['text_input']"
    press_until Return 2 "$applied" && return 0
    wait_for_state "$STATE" "$applied" "editing dt did not apply"
}

# Holds KEY until the state dump meets CONDITION, pressing again (at most TRIES times) when a
# frame slower than hold_key's hold missed it on a loaded machine; 1 if it never did.
press_until() {
    local key=$1 tries=$2 condition=$3
    for _ in $(seq "$tries"); do
        hold_key "$key"
        for _ in $(seq 40); do
            dump_now "$STATE"
            "$PYTHON" -c 'import json, sys; d = json.load(open(sys.argv[1])); sys.exit(0 if eval(sys.argv[2]) else 1)' \
                "$STATE" "$condition" && return 0
            sleep 0.05
        done
    done
    return 1
}

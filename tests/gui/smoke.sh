#!/usr/bin/env bash
# The default preset runs 120 fixed frames, writes a screenshot that shows the lab (not a blank
# window) and a state dump whose simulated time advanced by exactly 120 x 0.016 s.
# Usage: smoke.sh <particle-lab binary> <source dir>
APP=$1
SRC=$2
source "$SRC/tests/gui/gui_test_lib.bash"
make_workdir

code=0
timeout 60 "$APP" --frames 120 --fixed-frame-dt 0.016 --screenshot "$WORK/shot.png" --dump-state "$WORK/state.json" \
    2>"$WORK/err.txt" || code=$?
[ "$code" -eq 0 ] || fail "exit code $code; stderr: $(cat "$WORK/err.txt")"
[ -s "$WORK/shot.png" ] || fail "no screenshot written"
[ -s "$WORK/state.json" ] || fail "no state dump written"

# Whole window, and the 3D view in the centre (drawn too, not just the panels around it).
png_stats "$WORK/shot.png" 0,0,1,1 0.3,0.1,0.55,0.55 >"$WORK/stats.txt"
{ read -r width height; read -r sd colours; read -r view_sd view_colours; } <"$WORK/stats.txt"
echo "screenshot ${width}x${height}: brightness sd $sd, $colours colours; 3D view sd $view_sd, $view_colours colours"
[ "$width" -ge 640 ] && [ "$height" -ge 480 ] || fail "screenshot too small: ${width}x${height}"
"$PYTHON" -c "import sys; sys.exit(0 if $sd > 8 and $colours > 50 else 1)" || fail "the screenshot looks blank"
"$PYTHON" -c "import sys; sys.exit(0 if $view_sd > 3 and $view_colours > 20 else 1)" || fail "the 3D view looks empty"

json_check "$WORK/state.json" 'd["t"] > 1.5' "simulated time did not advance"
# Frame-rate independent: 120 frames x 0.016 s at dt = 0.002 s are exactly 960 steps.
json_check "$WORK/state.json" 'd["frames"] == 120 and d["base_steps"] == 960' "wrong number of frames or steps"
json_check "$WORK/state.json" 'not d["paused"] and not d["dirty"] and d["preset"].endswith("default.json")' \
    "unexpected session flags"
json_check "$WORK/state.json" \
    'all(all(abs(c) < 1e3 for c in p["position"]) for v in d["variants"] for p in v["particles"])' \
    "particle positions are not finite"
echo "OK"

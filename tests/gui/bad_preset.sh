#!/usr/bin/env bash
# A preset that does not load is bad input: exit 2, every error printed with its JSON path, before
# any window is opened (the checks run without a display). Bad options are refused the same way.
# Usage: bad_preset.sh <particle-lab binary> <source dir>
APP=$1
SRC=$2
source "$SRC/tests/gui/gui_test_lib.bash"
make_workdir

"$PYTHON" - "$SRC/presets/default.json" "$WORK/bad.json" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
d["particles"][0]["mass"] = -1
d["contact"]["restitution"] = 1.5
json.dump(d, open(sys.argv[2], "w"))
PY

expect_exit_2() {
    local what=$1
    shift
    local code=0
    # Without a display: reaching for a window would fail with exit code 1, not 2.
    timeout 20 env -u DISPLAY "$APP" "$@" >"$WORK/out.txt" 2>"$WORK/err.txt" || code=$?
    [ "$code" -eq 2 ] || fail "$what: exit code $code, expected 2; stderr: $(cat "$WORK/err.txt")"
}

expect_exit_2 "invalid preset" "$WORK/bad.json" --frames 5
grep -q "particles\[0\]\.mass" "$WORK/err.txt" || fail "the mass error is not reported: $(cat "$WORK/err.txt")"
grep -q "contact\.restitution" "$WORK/err.txt" || fail "the restitution error is not reported: $(cat "$WORK/err.txt")"
grep -q "bad.json" "$WORK/err.txt" || fail "the file is not named: $(cat "$WORK/err.txt")"

expect_exit_2 "missing preset" "$WORK/does-not-exist.json" --frames 5
grep -q "does-not-exist.json" "$WORK/err.txt" || fail "the missing file is not named: $(cat "$WORK/err.txt")"

printf '{ "format": "particle-lab-preset", ' >"$WORK/broken.json"
expect_exit_2 "broken JSON" "$WORK/broken.json" --frames 5

expect_exit_2 "negative frame count" --frames -3
grep -q -- "--frames" "$WORK/err.txt" || fail "the bad option is not named: $(cat "$WORK/err.txt")"
expect_exit_2 "zero time scale" --time-scale 0
grep -q -- "--time-scale" "$WORK/err.txt" || fail "the bad option is not named: $(cat "$WORK/err.txt")"
echo "OK"

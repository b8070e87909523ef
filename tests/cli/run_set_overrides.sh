#!/usr/bin/env bash
# --set KEY=VALUE overrides a preset field before the preset is read: the run starts from the
# overridden value; a bad value gets the reader's own message (the same as for the file); a key
# the schema does not have, an index past the end and a malformed KEY=VALUE are errors naming it.
set -euo pipefail
bin=$1 src=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
preset=$src/presets/default.json

"$bin" run "$preset" --duration 0.002 --set 'particles[0].velocity=[5,5,0]' --set drag.model=none --out "$tmp/set.csv"
python3 - "$tmp/set.csv" <<'PY'
import csv, sys
r = next(csv.DictReader(open(sys.argv[1])))
assert (r["vx_m_s"], r["vy_m_s"], r["vz_m_s"]) == ("5", "5", "0"), r
PY
# A different drag coefficient changes the run; the same one does not.
cd=$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["drag"]["cd"])' "$preset")
"$bin" run "$preset" --duration 1 > "$tmp/plain.txt"
"$bin" run "$preset" --duration 1 --set "drag.cd=$cd" > "$tmp/same.txt"
"$bin" run "$preset" --duration 1 --set drag.cd=0.6 > "$tmp/cd.txt"
cmp -s "$tmp/plain.txt" "$tmp/same.txt" || fail "--set drag.cd=$cd (its own value) changed the run"
! cmp -s "$tmp/plain.txt" "$tmp/cd.txt" || fail "--set drag.cd=0.6 changed nothing"

expect_2() {  # expect_2 MESSAGE ARGS...: exit 2 and MESSAGE on stderr
    local message=$1
    shift
    set +e
    "$bin" run "$@" > /dev/null 2> "$tmp/err.txt"
    local code=$?
    set -e
    [ "$code" -eq 2 ] || fail "$*: expected exit 2, got $code"
    grep -qF -- "$message" "$tmp/err.txt" || fail "$*: no '$message' in: $(cat "$tmp/err.txt")"
}
# The same message as the reader gives for the file with that value.
python3 -c 'import json,sys; d=json.load(open(sys.argv[1])); d["drag"]["cd"]=-1; json.dump(d, open(sys.argv[2],"w"))' "$preset" "$tmp/bad.json"
set +e
"$bin" run "$tmp/bad.json" 2> "$tmp/file_err.txt"
set -e
file_message=$(grep -m1 "drag.cd" "$tmp/file_err.txt") || fail "the file with cd -1 gave no drag.cd error"
expect_2 "$file_message" "$preset" --set drag.cd=-1
expect_2 "drag.cdd" "$preset" --set drag.cdd=1
expect_2 "particles has 1 element, so [3] names nothing" "$preset" --set 'particles[3].mass=1'
expect_2 "drag.model is not an object" "$preset" --set drag.model.x=1
expect_2 "expected KEY=VALUE" "$preset" --set drag.cd
# Other commands take --set too.
"$bin" compare "$src/presets/drag_models.json" --duration 1 --json > "$tmp/c0.json"
"$bin" compare "$src/presets/drag_models.json" --duration 1 --set 'particles[0].velocity=[0,1,0]' --json > "$tmp/c1.json"
python3 - "$tmp/c0.json" "$tmp/c1.json" <<'PY'
import json, sys
apex = [json.load(open(f))["variants"][0]["particle"]["apex_height_m"] for f in sys.argv[1:]]
assert apex[1] < apex[0], apex  # a slower throw up does not rise as high
PY
# validate checks the preset as overridden, with the same messages.
"$bin" validate "$preset" --set drag.cd=0.6 > "$tmp/valid.txt" || fail "validate --set drag.cd=0.6 refused a valid value"
grep -q '^ok: ' "$tmp/valid.txt" || fail "validate --set: no ok line"
set +e
"$bin" validate "$preset" --set drag.cd=-1 > /dev/null 2> "$tmp/validate_err.txt"
code=$?
set -e
[ "$code" -eq 2 ] || fail "validate --set drag.cd=-1: expected exit 2, got $code"
grep -qF "drag.cd: must be > 0, got -1" "$tmp/validate_err.txt" || fail "validate --set drag.cd=-1: $(cat "$tmp/validate_err.txt")"
echo OK

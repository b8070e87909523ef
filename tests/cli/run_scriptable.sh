#!/usr/bin/env bash
# `run` in scripts: "-" reads the preset from standard input and writes --out / --events to
# standard output; --particles filters the rows; --quiet silences warnings; progress appears on
# a terminal only; a very large trajectory is announced with a warning naming --every and
# --particles; NAME.npy writes the same numbers as the CSV in NumPy's format.
set -euo pipefail
bin=$1 src=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

# Standard input and output.
"$bin" run - --duration 0.1 --out - < "$src/presets/default.json" > "$tmp/stdin.csv"
"$bin" run "$src/presets/default.json" --duration 0.1 --out "$tmp/file.csv"
cmp "$tmp/stdin.csv" "$tmp/file.csv" || fail "run - --out - differs from the file run"
"$bin" run "$src/presets/drop_restitution_0.8.json" --duration 2 --events - > "$tmp/events.csv"
head -1 "$tmp/events.csv" | grep -q '^t_s,variant,variant_index' || fail "--events - wrote no events CSV: $(head -2 "$tmp/events.csv")"
! grep -q "energy" "$tmp/events.csv" || fail "the summary was mixed into the events on standard output"
set +e
"$bin" run "$src/presets/default.json" --out - --events - > /dev/null 2> "$tmp/err.txt"
code=$?
set -e
[ "$code" -eq 2 ] && grep -q "both be standard output" "$tmp/err.txt" || fail "--out - --events -: exit $code, $(cat "$tmp/err.txt")"

# --particles: only those particles' rows and events.
"$bin" run "$src/presets/launch_velocities.json" --duration 1 --particles 0,2-3 --out "$tmp/some.csv" --events "$tmp/some_ev.csv"
python3 - "$tmp/some.csv" "$tmp/some_ev.csv" <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
assert {r["particle"] for r in rows} == {"0", "2", "3"}, {r["particle"] for r in rows}
events = list(csv.DictReader(open(sys.argv[2])))
assert events and {e["particle"] for e in events} <= {"0", "2", "3"}, events[:3]
PY
set +e
"$bin" run "$src/presets/launch_velocities.json" --particles 1,7 --out "$tmp/x.csv" 2> "$tmp/err.txt"
code=$?
set -e
[ "$code" -eq 2 ] && grep -q -- "--particles: particle 7 does not exist" "$tmp/err.txt" || fail "--particles 1,7: exit $code, $(cat "$tmp/err.txt")"

# --quiet: the warnings a drag-model preset raises are not printed.
"$bin" run "$src/presets/feather_vs_ball.json" --duration 1 --out /dev/null 2> "$tmp/warn.txt"
grep -q warning "$tmp/warn.txt" || fail "feather_vs_ball raised no warning to silence"
"$bin" run "$src/presets/feather_vs_ball.json" --duration 1 --out /dev/null --quiet 2> "$tmp/quiet.txt"
[ ! -s "$tmp/quiet.txt" ] || fail "--quiet still printed: $(cat "$tmp/quiet.txt")"

# Progress: on a terminal (script gives the command one) steps, rate and time left; in a pipe nothing.
export PARTICLE_LAB_PROGRESS_DELAY_S=0
script -qec "'$bin' run '$src/presets/many_particles.json' --duration 2" /dev/null > "$tmp/tty.txt"
grep -q "steps/s" "$tmp/tty.txt" && grep -q "left" "$tmp/tty.txt" || fail "no progress on a terminal: $(head -c 300 "$tmp/tty.txt")"
"$bin" run "$src/presets/many_particles.json" --duration 2 > /dev/null 2> "$tmp/pipe.txt"
! grep -q "steps/s" "$tmp/pipe.txt" || fail "progress shown in a pipe"
script -qec "'$bin' run '$src/presets/many_particles.json' --duration 2 --quiet" /dev/null > "$tmp/tty_quiet.txt"
! grep -q "steps/s" "$tmp/tty_quiet.txt" || fail "progress shown under --quiet"
unset PARTICLE_LAB_PROGRESS_DELAY_S

# A trajectory of 10 000 particles every step for 100 s: the warning comes before the run (which
# is cut short here).
timeout 2 "$bin" run "$src/presets/many_particles.json" --duration 100 --out /dev/null 2> "$tmp/big.txt" || true
grep -q "GB" "$tmp/big.txt" && grep -q -- "--every" "$tmp/big.txt" && grep -q -- "--particles" "$tmp/big.txt" ||
    fail "no size warning: $(cat "$tmp/big.txt")"

# .npy: the CSV's numbers, column by column (numpy alone reads it).
"$bin" run "$src/presets/dt_ladder.json" --duration 0.4 --out "$tmp/ladder.npy"
"$bin" run "$src/presets/dt_ladder.json" --duration 0.4 --out "$tmp/ladder.csv"
/usr/bin/python3 - "$tmp/ladder.npy" "$tmp/ladder.csv" <<'PY'
import csv, sys
import numpy as np
a = np.load(sys.argv[1])
rows = list(csv.DictReader(open(sys.argv[2])))
assert a.shape == (len(rows),), (a.shape, len(rows))
assert a.dtype.names == tuple(k for k in rows[0] if k != "variant"), a.dtype.names
for name in a.dtype.names:
    kind = int if a.dtype[name].kind == "u" else float
    assert [kind(r[name]) for r in rows] == a[name].tolist(), name
PY
echo OK

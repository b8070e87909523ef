#!/usr/bin/env bash
# sweep refuses bad input before running anything (exit 2, naming the field and the value, no
# output written); sweep-merge refuses shards of another sweep, a missing or repeated shard and
# an incomplete file; --resume skips a finished shard and will not overwrite another sweep's.
set -euo pipefail
bin=$1 src=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cd "$tmp"
preset=$src/presets/optimal_angle.json

expect_refusal() {  # expect_refusal TEXT ARGS...: exit 2 and TEXT on stderr
  local text=$1; shift
  local rc=0
  "$@" > out.txt 2> err.txt || rc=$?
  [ "$rc" -eq 2 ] || { echo "expected exit 2, got $rc: $*"; cat err.txt; exit 1; }
  grep -qF -- "$text" err.txt || { echo "expected '$text' in:"; cat err.txt; exit 1; }
}
expect_refusal "point 2 (drag.cd=-0.1): drag.cd: must be > 0, got -0.1" \
  "$bin" sweep "$preset" --axis drag.cd=0.3,0.2,-0.1 --out never.csv
[ ! -e never.csv ]
expect_refusal 'drag.model: unknown value "fast"' "$bin" sweep "$preset" --axis drag.model=none,fast
expect_refusal "drag.cdd: unknown key" "$bin" sweep "$preset" --axis drag.cdd=0.3:0.5:3
expect_refusal "launch.elevation_deg: must be a number in [-90, 90], got 100" \
  "$bin" sweep "$preset" --axis launch.elevation_deg=10:100:10
expect_refusal "--axis drag.cd: expected LOW:HIGH:COUNT" "$bin" sweep "$preset" --axis drag.cd=0.3:0.5
expect_refusal "--sample drag.cd: expected normal(MEAN,SD) or uniform(LOW,HIGH)" \
  "$bin" sweep "$preset" --sample "drag.cd=gauss(1,2)" --samples 3
expect_refusal "--metrics: unknown metric 'range'" "$bin" sweep "$preset" --axis drag.cd=0.3 --metrics range
expect_refusal "--shard: expected I/N" "$bin" sweep "$preset" --axis drag.cd=0.3 --shard 3/3
expect_refusal "not a whole number of steps" "$bin" sweep "$preset" --axis drag.cd=0.3 --duration 0.0005

axes=(--axis drag.cd=0.2:0.6:5 --duration 1 --metrics apex_height_m)
for i in 0 1; do "$bin" sweep "$preset" "${axes[@]}" --shard $i/2 --out s$i.csv; done
"$bin" sweep "$preset" --axis drag.cd=0.1:0.6:5 --duration 1 --metrics apex_height_m --shard 1/2 --out other1.csv
expect_refusal "shard 1/2 is missing" "$bin" sweep-merge s0.csv
expect_refusal "are both shard 0/2" "$bin" sweep-merge s0.csv s0.csv s1.csv
expect_refusal "not shards of one sweep" "$bin" sweep-merge s0.csv other1.csv
head -n 5 s1.csv > cut.csv
expect_refusal "cut.csv: shard 1/2 (contiguous) lacks point" "$bin" sweep-merge s0.csv cut.csv
expect_refusal "not a sweep CSV file" "$bin" sweep-merge "$preset"

# --resume: a finished shard is not redone (its file is left as it is, byte for byte and in time).
touch -d '2001-01-01' s1.csv
"$bin" sweep "$preset" "${axes[@]}" --shard 1/2 --out s1.csv --resume 2> resume.txt
grep -q "already holds shard 1/2" resume.txt
[ "$(stat -c %Y s1.csv)" = "$(date -d '2001-01-01' +%s)" ]
# ... an incomplete one is run again ...
cp cut.csv s1.csv
"$bin" sweep "$preset" "${axes[@]}" --shard 1/2 --out s1.csv --resume 2> resume.txt
grep -q "running it again" resume.txt
"$bin" sweep-merge s0.csv s1.csv > /dev/null
# ... and another sweep's file is not overwritten.
expect_refusal "holds shard 1/2 of sweep" "$bin" sweep "$preset" "${axes[@]}" --shard 1/2 --out other1.csv --resume
# A failed write is a runtime failure (exit 1) that says why.
rc=0
"$bin" sweep "$preset" "${axes[@]}" --out "$tmp/no/such/dir/out.csv" 2> err.txt || rc=$?
[ "$rc" -eq 1 ] && grep -q "cannot write" err.txt || { echo "expected exit 1, got $rc"; cat err.txt; exit 1; }
echo ok

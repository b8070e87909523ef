#!/usr/bin/env bash
# Bad command-line input gets a clear message naming the option and exit code 2; help exits 0.
set -euo pipefail
bin=$1 src=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
preset="$src/presets/default.json"

expect() {  # expected-exit-code text-the-message-must-contain args...
  local want=$1 text=$2
  shift 2
  set +e
  "$bin" "$@" > "$tmp/out.txt" 2> "$tmp/err.txt"
  local code=$?
  set -e
  [ "$code" -eq "$want" ] || { echo "particle-lab $*: expected exit $want, got $code"; cat "$tmp/out.txt" "$tmp/err.txt"; exit 1; }
  grep -q -- "$text" "$tmp/out.txt" "$tmp/err.txt" || { echo "particle-lab $*: no '$text' in:"; cat "$tmp/out.txt" "$tmp/err.txt"; exit 1; }
}

expect 2 "--bogus" run "$preset" --bogus
expect 2 "PRESET is required" run
expect 2 "--duration: must be a number > 0, got 'abc'" run "$preset" --duration abc
expect 2 "--duration: must be a number > 0" compare "$preset" --duration -1
expect 2 "--every: must be a whole number >= 1" run "$preset" --every 0
expect 2 "no such file" run "$tmp/missing.json"
expect 2 "--methods: unknown method 'rk5'" accuracy "$preset" --methods rk4,rk5
expect 2 "--dt: expected a comma-separated list" accuracy "$preset" --dt 0.01,x
expect 2 "--baseline: no variant" compare "$src/presets/drag_models.json" --baseline nope
expect 2 "--tolerance: must be a number > 0" advise "$preset" --tolerance 0
expect 2 "--time-tolerance: must be a number > 0" advise "$preset" --time-tolerance 0
expect 2 "--speed-tolerance: must be a number > 0, got 'x'" advise "$preset" --speed-tolerance x
expect 2 "--relative-tolerance: must be a number >= 0, got '-0.1'" advise "$preset" --relative-tolerance -0.1
expect 2 "--csv excludes --json" accuracy "$preset" --csv --json
expect 2 "--threads" bench --threads two
expect 1 "--out: cannot open" run "$preset" --duration 0.01 --out "$tmp/no/such/dir/traj.csv"
expect 0 "Subcommands:" --help
for c in run validate compare accuracy stability advise bench; do
  expect 0 "Usage: particle-lab $c" "$c" --help
  grep -q "$c" "$tmp/out.txt"
done
echo ok

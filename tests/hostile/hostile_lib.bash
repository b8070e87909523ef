# Shared by tests/hostile/*.sh: bash SCRIPT PARTICLE_LAB SOURCE_DIR.
# expect_exit drives particle-lab in a child with a memory bound (prlimit --as, the address
# space: setrlimit RLIMIT_AS) and a time bound (timeout), then checks the exit code and that
# stderr+stdout match a regular expression.
set -euo pipefail
app=$1
src=$2
gen="python3 $src/tests/hostile/gen.py"
work=$(mktemp -d "${TMPDIR:-/tmp}/pl_hostile.XXXXXX")
trap 'rm -rf "$work"' EXIT
failures=0
# AddressSanitizer reserves terabytes of address space for its shadow memory at start-up, so an
# instrumented binary (./lab sanitize) cannot run under an address-space bound at all: there the
# cases keep their time bound and exit checks, and the release build (./lab test) checks memory.
as_bound=1
# grep reads all of ldd's output (grep -q stops at the first match, ldd then dies of SIGPIPE
# and, under pipefail, the test took an instrumented binary for a plain one now and then).
if ldd "$app" 2>/dev/null | grep libasan >/dev/null; then
  as_bound=0
  echo "note: $app is built with AddressSanitizer: no address-space bound in this run" >&2
fi

fail() {
  echo "FAIL: $*" >&2
  failures=$((failures + 1))
}

# expect_exit NAME MEMORY_MB SECONDS EXIT_CODE REGEX -- COMMAND...
expect_exit() {
  local name=$1 mem=$2 seconds=$3 want=$4 pattern=$5
  shift 6
  local out=$work/$name.out start end code=0
  start=$(date +%s.%N)
  local limit=(prlimit --as=$((mem * 1024 * 1024)) --)
  # Instrumented code runs several times slower: its time bounds are four times as generous.
  [ "$as_bound" -eq 1 ] || { limit=(); seconds=$((seconds * 4)); }
  timeout --kill-after=2 "$seconds" "${limit[@]}" "$@" >"$out" 2>&1 || code=$?
  end=$(date +%s.%N)
  local took
  took=$(awk -v a="$start" -v b="$end" 'BEGIN { printf "%.2f", b - a }')
  if [ "$code" -eq 124 ] || [ "$code" -eq 137 ]; then
    fail "$name: still running after $seconds s (memory bound $mem MB)"
    return
  fi
  if [ "$code" -ne "$want" ]; then
    fail "$name: exit $code, expected $want; output:"
    head -c 2000 "$out" >&2
    return
  fi
  if ! grep -Eq -- "$pattern" "$out"; then
    fail "$name: output does not match /$pattern/:"
    head -c 2000 "$out" >&2
    return
  fi
  echo "ok: $name (exit $code, ${took} s, under $mem MB)"
}

finish() {
  if [ "$failures" -gt 0 ]; then
    echo "$failures hostile case(s) failed" >&2
    exit 1
  fi
}

#!/usr/bin/env bash
# `validate`: exit 0 with "ok: N particles, M variants" for a good preset; exit 2 printing every
# error (with its JSON path) for a bad one, a missing file or a directory.
set -euo pipefail
bin=$1 src=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

out=$("$bin" validate "$src/presets/drag_models.json")
[ "$out" = "ok: 1 particle, 4 variants" ] || { echo "unexpected: $out"; exit 1; }

cat > "$tmp/bad.json" <<'JSON'
{ "format": "particle-lab-preset", "version": 1, "name": "bad",
  "room": { "center": [0, 0, 0], "size": [10, 6, 10] },
  "integrator": { "method": "semi_implicit_euler", "dt": 0.002 },
  "particles": [ { "position": [0, 0, 0], "velocity": [0, 0, 0], "mass": -1, "radius": 0.033 },
                 { "position": [0, 0, 0], "velocity": [0, 0, 0], "mass": 1, "radius": 0.033, "colour": 3 } ] }
JSON
expect_exit_2() {
  set +e
  "$bin" validate "$1" > "$tmp/out.txt" 2> "$tmp/err.txt"
  local code=$?
  set -e
  [ "$code" -eq 2 ] || { echo "validate $1: expected exit 2, got $code"; cat "$tmp/out.txt" "$tmp/err.txt"; exit 1; }
  [ -s "$tmp/err.txt" ] || { echo "validate $1: no error message"; exit 1; }
}
expect_exit_2 "$tmp/bad.json"
grep -q "particles\[0\].mass" "$tmp/err.txt" || { echo "missing mass error:"; cat "$tmp/err.txt"; exit 1; }
grep -q "particles\[1\].colour" "$tmp/err.txt" || { echo "missing unknown-key error (every error must be listed):"; cat "$tmp/err.txt"; exit 1; }
expect_exit_2 "$tmp/does-not-exist.json"
expect_exit_2 "$tmp"
echo ok

#!/usr/bin/env bash
# fuzz/preset.dict holds exactly the tokens `particle-lab schema --fuzz-dict` generates from the
# preset rows (before the hand-added marker): regenerate it when a key or a name changes.
set -euo pipefail
bin=$1 src=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$bin" schema --fuzz-dict > "$tmp/generated.txt"
grep -q '^# ---- hand-added' "$src/fuzz/preset.dict" || { echo "fuzz/preset.dict has no '# ---- hand-added' marker"; exit 1; }
sed '/^# ---- hand-added/q' "$src/fuzz/preset.dict" | grep -v '^#' > "$tmp/dict.txt"
if ! diff -u "$tmp/dict.txt" "$tmp/generated.txt"; then
  echo "fuzz/preset.dict differs from 'particle-lab schema --fuzz-dict' (diff above: - file, + generated)"
  exit 1
fi
grep -qx '"\\"seed\\""' "$tmp/generated.txt" || { echo "no seed token generated"; exit 1; }
echo ok

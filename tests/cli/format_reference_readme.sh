#!/usr/bin/env bash
# The format reference README.md embeds is the text `particle-lab validate --format` generates
# from the preset rows: edit a row, then paste the new output into the README block.
set -euo pipefail
bin=$1 src=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$bin" validate --format > "$tmp/printed.txt"
# The ```text block that follows the "Keys (SI units" line.
awk '/^Keys \(SI units/ { after = 1 } after && /^```text$/ { inside = 1; next } inside && /^```$/ { exit } inside' \
  "$src/README.md" > "$tmp/readme.txt"
[ -s "$tmp/readme.txt" ] || { echo "README.md has no format reference block after 'Keys (SI units'"; exit 1; }
if ! diff -u "$tmp/readme.txt" "$tmp/printed.txt"; then
  echo "README.md's format reference differs from 'particle-lab validate --format' (diff above: - README, + printed)"
  exit 1
fi
grep -q '^  world.wind.seed ' "$tmp/printed.txt" || { echo "the reference lists no world.wind.seed"; exit 1; }
echo ok

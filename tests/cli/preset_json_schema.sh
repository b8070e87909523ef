#!/usr/bin/env bash
# `particle-lab schema` prints a valid JSON Schema (draft 2020-12) that every shipped preset
# passes and every bad preset fails, but those tests/cli/check_preset_schema.py lists with the
# reason a schema cannot tell; the loader refuses every one of the catalogue too.
set -euo pipefail
bin=$1 src=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$bin" schema > "$tmp/schema.json"
/usr/bin/python3 "$src/tests/cli/check_preset_schema.py" "$tmp/schema.json" "$src/presets" "$src/tests/bad_presets"
for f in "$src"/tests/bad_presets/*.json; do
  set +e
  "$bin" validate "$f" > /dev/null 2>&1
  code=$?
  set -e
  [ "$code" -eq 2 ] || { echo "$(basename "$f"): the loader accepted it (exit $code)"; exit 1; }
done
echo ok

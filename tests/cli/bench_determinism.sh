#!/usr/bin/env bash
# `bench --quick`: every size, scene and method has a row, and the state hash of the final
# positions does not depend on the thread count.
set -euo pipefail
bin=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

"$bin" bench --quick --threads 1,2 > "$tmp/bench.txt"
python3 - "$tmp/bench.txt" <<'PY'
import sys
rows = [l.split() for l in open(sys.argv[1]) if l.startswith(("gravity ", "gravity+"))]
assert len(rows) == 3 * 2 * 6 * 2, len(rows)
hashes = {}
for r in rows:
    hashes.setdefault((r[0], r[1], r[2]), set()).add(r[-1])
assert all(len(h) == 1 for h in hashes.values()), "thread count changed the final state"
PY
echo ok

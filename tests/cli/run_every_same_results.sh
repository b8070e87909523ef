#!/usr/bin/env bash
# `run` advances every variant from one output point to the next in one call (several steps per
# kernel call): the output interval must not change the results. 10 000 particles: --every 1
# (one step per call) and --every 64 write the same event rows (grouped per interval, so compared
# as sets); --every 20 and --every 50 the same states; the summary without CSV output (its own
# interval) is the same text, and reports the event counts of the rows. Collisions off: with them
# every kernel call is one step.
set -euo pipefail
bin=$1 src=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

preset="$src/presets/many_particles.json"
"$bin" run "$preset" --set collisions.enabled=false --duration 0.4 --every 1 --events "$tmp/e1.csv" > "$tmp/summary1.txt" 2> /dev/null
"$bin" run "$preset" --set collisions.enabled=false --duration 0.4 --every 64 --events "$tmp/e64.csv" > /dev/null 2>&1
"$bin" run "$preset" --set collisions.enabled=false --duration 0.4 --every 20 --out "$tmp/t20.csv" 2> /dev/null
"$bin" run "$preset" --set collisions.enabled=false --duration 0.4 --every 50 --out "$tmp/t50.csv" 2> /dev/null
"$bin" run "$preset" --set collisions.enabled=false --duration 0.4 > "$tmp/summary.txt" 2> /dev/null
# One step per call and 256 per output point: the same summary, ledger digits included.
cmp "$tmp/summary1.txt" "$tmp/summary.txt" || { diff "$tmp/summary1.txt" "$tmp/summary.txt"; exit 1; }
python3 - "$tmp" <<'PY'
import csv, sys
d = sys.argv[1]
e1 = list(csv.reader(open(d + "/e1.csv")))
e64 = list(csv.reader(open(d + "/e64.csv")))
assert e1[0] == e64[0]
assert len(e1) > 100, len(e1)
assert sorted(e1[1:]) == sorted(e64[1:]), "event rows differ"
def rows_at(path, t):
    return sorted(tuple(r.values()) for r in csv.DictReader(open(path)) if r["t_s"] == t)
for t in ("0.2", "0.4"):  # 100 and 200 steps of 2 ms: written by both
    a, b = rows_at(d + "/t20.csv", t), rows_at(d + "/t50.csv", t)
    assert len(a) == 10000 and a == b, ("states differ at t =", t)
t50 = sorted(set(float(r["t_s"]) for r in csv.DictReader(open(d + "/t50.csv"))))
assert len(t50) == 5, t50  # t = 0, 50 dt, 100 dt, 150 dt, 0.4 s
summary = open(d + "/summary.txt").read()
kinds = {}
for r in e1[1:]:
    kinds[r[7]] = kinds.get(r[7], 0) + 1
for kind, n in kinds.items():
    assert f"{n} {kind}" in summary or f"{kind} {n}" in summary or f"{kind}: {n}" in summary, (kind, n, summary)
PY
echo ok

#!/usr/bin/env bash
# Every JSON document carries schema_version; compare --csv and advise --csv hold the JSON's
# names and numbers (flattened), and bench --csv one row per measurement at full precision.
set -euo pipefail
bin=$1 src=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

"$bin" compare "$src/presets/drag_models.json" --duration 2 --json > "$tmp/c.json"
"$bin" compare "$src/presets/drag_models.json" --duration 2 --csv > "$tmp/c.csv"
"$bin" advise "$src/presets/default.json" --json > "$tmp/a.json"
"$bin" advise "$src/presets/default.json" --csv > "$tmp/a.csv"
"$bin" accuracy "$src/presets/default.json" --methods rk4 --duration 0.5 --json > "$tmp/acc.json"
"$bin" stability --quick --json > "$tmp/s.json"
"$bin" bench --quick --csv > "$tmp/b.csv"
python3 - "$tmp" <<'PY'
import csv, json, sys
d = sys.argv[1]
docs = {n: json.load(open(f"{d}/{n}.json")) for n in ("c", "a", "acc", "s")}
for n, doc in docs.items():
    assert doc["schema_version"] == 2, (n, list(doc)[:3])

def flat(obj, prefix=""):
    out = {}
    for k, v in obj.items():
        name = prefix + k
        if isinstance(v, dict): out.update(flat(v, name + "."))
        elif not isinstance(v, list): out[name] = v
    return out

def same(cell, value):
    if value is None: return cell == ""
    if isinstance(value, bool): return cell == ("true" if value else "false")
    if isinstance(value, (int, float)): return float(cell) == value
    return cell == value

rows = list(csv.DictReader(open(f"{d}/c.csv")))
variants = docs["c"]["variants"]
assert len(rows) == len(variants) == 4, len(rows)
for row, v in zip(rows, variants):
    for k, value in flat(v).items():
        if k not in ("physics_time_s", "cost_s_per_s", "difference_to_baseline.cost_s_per_s"):  # timed: differ per run
            assert same(row[k], value), (k, row[k], value)

rows = list(csv.DictReader(open(f"{d}/a.csv")))
runs = [(v, r) for v in docs["a"]["variants"] for r in v["runs"]]
assert len(rows) == len(runs) and len(runs) >= 4, len(rows)
for row, (v, r) in zip(rows, runs):
    assert row["label"] == v["label"] and row["runs.drag"] == r["drag"], row
    assert float(row["runs.landing_difference_m"]) == r["landing_difference_m"], row
    assert row["verdicts"] == "; ".join(v["verdicts"]), row["verdicts"]

rows = list(csv.DictReader(open(f"{d}/b.csv")))
assert len(rows) == 3 * 2 * 6, len(rows)
assert list(rows[0]) == ["scene", "method", "particles", "threads", "steps", "wall_s", "particle_steps_per_s", "state_hash_fnv1a"]
for r in rows:
    assert abs(float(r["particle_steps_per_s"]) - int(r["particles"]) * int(r["steps"]) / float(r["wall_s"])) <= 1e-9 * float(r["particle_steps_per_s"]), r
PY
echo OK

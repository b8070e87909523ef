#!/usr/bin/env bash
# Sweep throughput: scenes per second of a 1,000-point sweep (presets/optimal_angle.json, quadratic
# drag, launch elevation 10..80 degrees in 1,000 steps, 6.5 s simulated per scene with RK4 at
# dt = 1 ms) on 1 and on 2 threads, and the speed-up. Each setting runs REPEATS times (default 5),
# alternating 1 and 2 threads so that a slow spell of a shared machine hits both; the best wall
# time of each counts. The CPU time (user + system) of each run shows the parallel overhead
# apart from the machine's load: on 2 free cores, wall speed-up = 2 x cpu(1) / cpu(2). The two
# outputs must be identical (results do not depend on the thread count).
#   bench/sweep_scaling.sh [PARTICLE_LAB] [REPEATS]
set -euo pipefail
cd "$(dirname "$(readlink -f "$0")")/.."
bin=${1:-build/release/particle-lab}
repeats=${2:-5}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
python3 - "$bin" "$repeats" "$tmp" <<'PY'
import os, subprocess, sys, time
bin, repeats, tmp = sys.argv[1], int(sys.argv[2]), sys.argv[3]
points = 1000
args = [bin, "sweep", "presets/optimal_angle.json", "--axis", f"launch.elevation_deg=10:80:{points}",
        "--duration", "6.5", "--metrics", "range_at_first_impact_m"]
best = {1: (float("inf"), 0.0), 2: (float("inf"), 0.0)}  # threads -> (wall s, cpu s of that run)
for _ in range(repeats):
    for t in (1, 2):
        start = time.perf_counter()
        p = subprocess.Popen(args + ["--threads", str(t), "--out", f"{tmp}/t{t}.csv"])
        _, status, usage = os.wait4(p.pid, 0)
        wall = time.perf_counter() - start
        if status != 0: sys.exit(f"sweep failed: {status}")
        if wall < best[t][0]: best[t] = (wall, usage.ru_utime + usage.ru_stime)
if open(f"{tmp}/t1.csv").read() != open(f"{tmp}/t2.csv").read(): sys.exit("outputs differ between 1 and 2 threads")
print(f"sweep of {points} scenes, {os.cpu_count()} hardware threads, load average {os.getloadavg()[0]:.1f}; best of {repeats}:")
for t in (1, 2):
    wall, cpu = best[t]
    print(f"  {t} thread{'s' if t > 1 else ' '}: {wall:.3f} s wall {points / wall:8.1f} scenes/s, {cpu:.3f} s cpu")
w1, c1 = best[1]; w2, c2 = best[2]
print(f"  speed-up on 2 threads: {w1 / w2:.2f}x wall (target 1.8x); cpu(1)/cpu(2) = {c1 / c2:.2f} "
      f"(2 free cores would give {2 * c1 / c2:.2f}x)")
PY

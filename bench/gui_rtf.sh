#!/usr/bin/env bash
# Real-time factor of the GUI's physics thread: presets/many_particles.json (quadratic drag,
# walls, dt = 2 ms; collisions off) with its emitter at 1e5 and at 1e6 particles, the GUI under Xvfb drawing at
# most 10 frames per second (--max-fps 10). After WARMUP seconds of wall time (default 10: the
# emitter, the first frames) two state dumps MEASURE seconds apart (default 20) give
#   RTF = simulated seconds advanced / wall seconds between them,
# and the status bar's smoothed numbers at the second dump (physics ms and render ms per frame,
# frames per second). The target: RTF >= 1 at 1e5 on 2 cores. A shared machine's load lowers
# every number; the load average is printed with them. PL_MAX_FPS (default 10) and PL_COUNTS
# (default "100000 1000000") change the frame cap and the particle counts.
# PL_SCENE=gas measures colliding particles instead: the dilute gas of the collision benchmark
# (balls of 5 mm, e = 1, no gravity or drag, the density of 1e4 balls in a 2 m box, the room
# scaled with n), dt = 2 ms; PL_SCENE=pile the same balls poured into a room whose floor holds a
# tenth of them side by side (gravity, e = 0.5, mu = 0.5: they settle about ten deep and sleep).
#   bench/gui_rtf.sh [PARTICLE_LAB] [WARMUP] [MEASURE]
set -euo pipefail
cd "$(dirname "$(readlink -f "$0")")/.."
bin=$(readlink -f "${1:-build/native/particle-lab}")
warmup=${2:-10}
measure=${3:-20}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
export XDG_CONFIG_HOME="$tmp/config"  # no saved layout or camera
if [ -x /usr/bin/python3 ]; then python=/usr/bin/python3; else python=python3; fi
bash tests/gui/with_display.sh "$python" - "$bin" "$warmup" "$measure" "$tmp" <<'PY'
import json, os, signal, subprocess, sys, time
bin, warmup, measure, tmp = sys.argv[1], float(sys.argv[2]), float(sys.argv[3]), sys.argv[4]
base = json.load(open("presets/many_particles.json"))
kind = os.environ.get("PL_SCENE", "drag")

def scene_for(n):
    if kind == "drag":
        return dict(base, name=f"{n} particles", emitter=dict(base["emitter"], count=n),
                    collisions={"enabled": False})
    s = dict(base, name=f"{n} colliding particles ({kind})")
    s["integrator"] = {"method": "semi_implicit_euler", "dt": 0.002}
    ball = {"count": n, "seed": 5, "mass_min": 0.001, "mass_max": 0.001, "radius_min": 0.005, "radius_max": 0.005}
    if kind == "gas":
        side = 2.0 * (n / 1e4) ** (1 / 3)
        s["room"] = {"center": [0, 0, 0], "size": [side] * 3}
        s["world"] = {"gravity": [0, 0, 0], "air": {"density": 1.225, "viscosity": 1.81e-5}}
        s["drag"] = {"model": "none"}
        s["contact"] = {"restitution": 1.0, "friction": 0.0, "rest_speed": 0.0}
        s["collisions"] = {"enabled": True, "restitution": 1.0, "friction": 0.0}
        s["emitter"] = dict(ball, region_min=[-0.475 * side] * 3, region_max=[0.475 * side] * 3, speed_min=0.5,
                            speed_max=2.0, direction=[0, 1, 0], spread_deg=180)
    else:
        side = 0.01 * (n / 10) ** 0.5
        s["room"] = {"center": [0, 0.5, 0], "size": [side, 1.0, side]}
        s["contact"] = {"restitution": 0.5, "friction": 0.5, "rest_speed": 0.05}
        s["collisions"] = {"enabled": True, "restitution": 0.5, "friction": 0.5}
        s["emitter"] = dict(ball, region_min=[-side / 2 + 0.01, 0.05, -side / 2 + 0.01],
                            region_max=[side / 2 - 0.01, 0.95, side / 2 - 0.01], speed_min=0, speed_max=0.5,
                            direction=[0, 1, 0], spread_deg=180)
    return s

def dump(p, path):
    if os.path.exists(path): os.remove(path)
    p.send_signal(signal.SIGUSR1)
    for _ in range(400):
        if os.path.exists(path) and os.path.getsize(path) > 0:
            return time.perf_counter(), json.load(open(path))
        time.sleep(0.025)
    sys.exit("no state dump")

print(f"{kind}: GUI physics thread, --max-fps {os.environ.get('PL_MAX_FPS', '10')}, dt = {base['integrator']['dt'] * 1e3:g} ms, {os.cpu_count()} hardware threads")
for n in [int(x) for x in os.environ.get("PL_COUNTS", "100000 1000000").split()]:
    scene = scene_for(n)
    preset = f"{tmp}/n{n}.json"
    json.dump(scene, open(preset, "w"))
    state = f"{tmp}/state.json"
    p = subprocess.Popen([bin, preset, "--max-fps", os.environ.get("PL_MAX_FPS", "10"), "--dump-state", state, "--frames", "100000000"],
                         stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    time.sleep(warmup)
    w1, d1 = dump(p, state)
    time.sleep(measure)
    w2, d2 = dump(p, state)
    p.terminate()
    p.wait()
    rtf = (d2["t"] - d1["t"]) / (w2 - w1)
    f = d2["frame_stats"]
    print(f"  {n:>9} particles: RTF {rtf:.2f} (t {d1['t']:.2f} -> {d2['t']:.2f} s in {w2 - w1:.1f} s wall), "
          f"status bar: physics {f['physics_ms']:.1f} ms, render {f['render_ms']:.1f} ms per frame, {f['fps']:.1f} FPS; "
          f"load average {os.getloadavg()[0]:.1f}")
PY

# The GUI's memory grows in proportion to the particles, at a bounded cost per particle, and its
# fixed part (plot history, fonts, the GL context) does not grow with them. Runs the app on
# emitter scenes of N1 and N2 particles for a few frames and takes the peak resident size of each
# (getrusage of the child): the slope (peak2 - peak1) / (N2 - N1) is the memory per particle.
# What it holds (README, "Memory"): the engine's state (about 122 B), the instance buffer the 3D
# view streams (32 B, and the driver's copy of it), and, under software rendering (Mesa llvmpipe,
# as here), the rasteriser's binned points (about 250-300 B per point drawn per frame). The
# bound of 650 B leaves room for that driver and fails on what the app used to hold (plot
# history and tracking state per particle: 2,000-2,600 B per particle at 2e6).
source "$(dirname "$0")/gui_test_lib.bash"
app=$1
src=$2
make_workdir

# grep reads all of ldd's output (grep -q stops at the first match, ldd then dies of SIGPIPE
# and, under pipefail, the test took an instrumented binary for a plain one now and then).
if ldd "$app" 2>/dev/null | grep libasan >/dev/null; then
    echo "skip: AddressSanitizer's shadow and quarantine memory hide the app's own (checked in the release build)"
    exit 0
fi

"$PYTHON" - "$app" "$src/presets/many_particles.json" "$WORK" <<'PY'
import json, os, subprocess, sys
app, preset, work = sys.argv[1:4]
scene = json.load(open(preset))
scene["collisions"] = {"enabled": False}  # the engine's state alone (the collision pass adds its own)

def peak_kb(count):
    scene["emitter"]["count"] = count
    path = os.path.join(work, f"many_{count}.json")
    json.dump(scene, open(path, "w"))
    p = subprocess.Popen([app, path, "--frames", "5", "--fixed-frame-dt", "0.016"],
                         stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    _, status, usage = os.wait4(p.pid, 0)
    if status != 0:
        sys.exit(f"FAIL: the app exited with status {status} on {count} particles: {p.stderr.read().decode()[:500]}")
    return usage.ru_maxrss  # KiB on Linux

# Both counts are past the 3D view's mesh limit (1e4), so both draw point sprites.
n1, n2 = 20_000, 200_000
k1, k2 = peak_kb(n1), peak_kb(n2)
per_particle = (k2 - k1) * 1024 / (n2 - n1)
print(f"peak resident: {k1 / 1024:.0f} MiB at {n1} particles, {k2 / 1024:.0f} MiB at {n2}: "
      f"{per_particle:.0f} bytes per particle")
if per_particle > 650:
    sys.exit(f"FAIL: {per_particle:.0f} bytes per particle, bound 650")
if k1 > 400 * 1024:
    sys.exit(f"FAIL: {k1 / 1024:.0f} MiB at {n1} particles: the fixed part grew past 400 MiB")
PY

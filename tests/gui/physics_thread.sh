#!/usr/bin/env bash
# Physics in its own thread keeps bit-identical replay: the GUI runs drag_models.json (six
# variants) at real time while drawing at 10 and at 60 frames per second, is paused with space
# at whatever step the thread reached, and every particle of every variant must equal, bit for
# bit, `particle-lab run` of the same preset for that many steps (.npy: exact doubles). The
# status bar's numbers (real-time factor, physics and render time) are in the state dump.
# Usage: physics_thread.sh <particle-lab binary> <source dir>
APP=$1
SRC=$2
source "$SRC/tests/gui/gui_test_lib.bash"
make_workdir
PRESET="$SRC/presets/drag_models.json"
STATE="$WORK/state.json"

for fps in 10 60; do
    start_app "$PRESET" --frames 1000000 --max-fps "$fps" --dump-state "$STATE"
    wait_for_state "$STATE" 'd["t"] > 1.0 and d["frame_stats"]["real_time_factor"] > 0' "the physics thread does not run at $fps fps"
    json_check "$STATE" 'd["frame_stats"]["render_ms"] > 0 and d["frame_stats"]["physics_ms"] >= 0' "no physics or render time at $fps fps"
    press space
    wait_for_state "$STATE" 'd["paused"]' "space did not pause"
    dump_now "$STATE"
    t=$(json_get "$STATE" 'repr(d["base_steps"] * 0.002)')
    steps=$(json_get "$STATE" 'd["base_steps"]')
    "$APP" run "$PRESET" --duration "$t" --out "$WORK/run.npy" -q || fail "particle-lab run --duration $t failed"
    "$PYTHON" - "$STATE" "$WORK/run.npy" "$steps" <<'PY' || fail "the GUI at $fps fps differs from the headless run after $steps steps"
import json, sys
import numpy as np
d = json.load(open(sys.argv[1]))
a = np.load(sys.argv[2])
steps = int(sys.argv[3])
last = a[a["step"] == steps]
assert len(last) > 0, f"the headless run has no row at step {steps}"
for v, variant in enumerate(d["variants"]):
    for i, p in enumerate(variant["particles"]):
        row = last[(last["variant_index"] == v) & (last["particle"] == i)]
        assert len(row) == 1, (v, i)
        gui = p["position"] + p["velocity"]
        cli = [float(row[0][k]) for k in ("x_m", "y_m", "z_m", "vx_m_s", "vy_m_s", "vz_m_s")]
        if gui != cli:
            sys.exit(f"variant {v} particle {i}: GUI {gui} != run {cli}")
PY
    quit_app
done
echo "OK"

#!/usr/bin/env bash
# Many particles on a CPU rasteriser are splatted on the CPU (app/point_splat.hpp) instead of
# drawn as GL points, and look the same: 30,000 balls (beyond the sphere meshes' 10,000) drawn
# both ways (PL_POINT_SPLAT=0 and 1) after the same fixed frames, and the 3D view's pixels
# compared. Under llvmpipe (Xvfb) the GL points are llvmpipe's own rasterisation, so this checks
# the splat against a real GL implementation: sizes, shading, depth order, the room's occlusion.
# Usage: point_splat.sh <particle-lab binary> <source dir>
APP=$1
SRC=$2
source "$SRC/tests/gui/gui_test_lib.bash"
make_workdir

"$PYTHON" - "$SRC/presets/many_particles.json" "$WORK/many.json" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
d["name"] = "30000 balls"
d["emitter"]["count"] = 30000
d["collisions"] = {"enabled": False}
json.dump(d, open(sys.argv[2], "w"))
PY

for splat in 0 1; do
    code=0
    PL_POINT_SPLAT=$splat timeout 120 "$APP" "$WORK/many.json" --frames 20 --fixed-frame-dt 0.02 \
        --screenshot "$WORK/shot$splat.png" --dump-state "$WORK/state$splat.json" 2>"$WORK/err.txt" || code=$?
    [ "$code" -eq 0 ] || fail "PL_POINT_SPLAT=$splat: exit code $code; stderr: $(cat "$WORK/err.txt")"
done
json_check "$WORK/state1.json" 'd["base_steps"] == 200' "the runs did not take the same 200 steps"

# Pixels of the 3D view's middle that differ by more than 24 of 255 in a channel, and how many of
# them show a ball (saturated colour) in either image.
cc -O2 -std=c11 -I/usr/include/stb -o "$WORK/png_diff" -x c - -lstb -lm <<'C' || fail "cannot build the PNG comparer"
#include <stdio.h>
#include <stdlib.h>
#include <stb_image.h>
int main(int argc, char** argv) {
    int w, h, n, w2, h2;
    unsigned char* a = stbi_load(argv[1], &w, &h, &n, 3);
    unsigned char* b = stbi_load(argv[2], &w2, &h2, &n, 3);
    if (!a || !b || w != w2 || h != h2) return 1;
    long all = 0, differ = 0, balls = 0;
    for (int y = h / 10; y < h * 6 / 10; ++y)
        for (int x = w * 3 / 10; x < w * 55 / 100; ++x) {
            const unsigned char* p = a + 3 * ((long)y * w + x);
            const unsigned char* q = b + 3 * ((long)y * w + x);
            int most = 0, hi = 0, lo = 255;
            for (int c = 0; c < 3; ++c) {
                int d = abs(p[c] - q[c]);
                if (d > most) most = d;
                if (q[c] > hi) hi = q[c];
                if (q[c] < lo) lo = q[c];
            }
            ++all;
            differ += most > 24;
            balls += hi > 60 && hi - lo > 0.45 * hi;
        }
    printf("%ld %ld %ld\n", all, differ, balls);
    return 0;
}
C
read -r all differ balls < <("$WORK/png_diff" "$WORK/shot0.png" "$WORK/shot1.png")
echo "3D view: $all pixels, $balls show a ball in the splat, $differ differ from the GL points"
"$PYTHON" -c "import sys; sys.exit(0 if $balls > 0.05 * $all else 1)" || fail "the splatted view shows too few balls"
"$PYTHON" -c "import sys; sys.exit(0 if $differ <= 0.005 * $all else 1)" || fail "the splat differs from the GL points"
echo "OK"

#!/usr/bin/env bash
# examples/classic_plots.py (quick settings) runs the CLI and writes its three figures: each a
# PNG of a sensible size with real content (many colours, not a blank canvas).
set -euo pipefail
bin=$1 src=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
/usr/bin/python3 "$src/examples/classic_plots.py" --bin "$bin" --presets "$src/presets" --out "$tmp" --quick > "$tmp/list.txt"
[ "$(wc -l < "$tmp/list.txt")" -eq 3 ] || { echo "expected three figures, got: $(cat "$tmp/list.txt")"; exit 1; }
/usr/bin/python3 - "$tmp" <<'PY'
import sys
import matplotlib.image as mpimg
import numpy as np
for name in ("drag_models.png", "work_precision.png", "stability_map.png"):
    path = f"{sys.argv[1]}/{name}"
    assert open(path, "rb").read(8) == b"\x89PNG\r\n\x1a\n", name
    img = mpimg.imread(path)[..., :3]
    h, w = img.shape[:2]
    assert w >= 600 and h >= 400, (name, w, h)
    colours = len(np.unique((img * 255).astype(np.uint8).reshape(-1, 3), axis=0))
    ink = float((img.mean(axis=2) < 0.9).mean())  # share of pixels that are not (near) white
    assert colours > 50 and 0.01 < ink < 0.6, (name, colours, ink)
    print(name, w, h, colours, round(ink, 3))
PY
echo OK

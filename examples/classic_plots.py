#!/usr/bin/env python3
"""The classic particle-lab plots from its command line, with pandas and matplotlib (Debian
python3-pandas, python3-matplotlib):

  drag_models.png     trajectories of one throw under each drag model (presets/drag_models.json)
  work_precision.png  end-point error against force evaluations per integrator (`accuracy --csv`)
  stability_map.png   stable / unstable cells over dt and drag stiffness per method (`stability --csv`)

Usage: examples/classic_plots.py [--bin PATH] [--presets DIR] [--out DIR] [--quick]
--bin defaults to particle-lab on PATH, else build/native or build/release in this checkout.
"""
import argparse
import io
import pathlib
import shutil
import subprocess
import sys

import matplotlib

matplotlib.use("Agg")  # files only: no display needed
import matplotlib.pyplot as plt
import pandas as pd

ROOT = pathlib.Path(__file__).resolve().parent.parent


def find_binary():
    on_path = shutil.which("particle-lab")
    if on_path:
        return on_path
    for build in ("native", "release"):
        candidate = ROOT / "build" / build / "particle-lab"
        if candidate.exists():
            return str(candidate)
    sys.exit("particle-lab not found: build it (./lab build) or pass --bin")


def cli_csv(binary, *args):
    """Runs `particle-lab ARGS` and reads the CSV it prints to standard output."""
    out = subprocess.run([binary, *args, "--quiet"], check=True, capture_output=True, text=True).stdout
    # keep_default_na=False: an empty variant label stays "" rather than NaN (the columns used
    # here are never empty, so they still read as numbers)
    return pd.read_csv(io.StringIO(out), keep_default_na=False)


def plot_drag_models(binary, presets, quick, path):
    duration = "1" if quick else "3"
    traj = cli_csv(binary, "run", str(presets / "drag_models.json"), "--duration", duration, "--out", "-")
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for (index, label), rows in traj[traj.particle == 0].groupby(["variant_index", "variant"]):
        ax.plot(rows.x_m, rows.height_m, label=label)
    ax.set_xlabel("x (m)")
    ax.set_ylabel("height above the floor (m)")
    ax.set_title(f"One throw under each drag model ({duration} s)")
    ax.legend()
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    plt.close(fig)


def plot_work_precision(binary, presets, quick, path):
    args = ["accuracy", str(presets / "default.json"), "--csv", "--duration", "0.5" if quick else "2"]
    if quick:
        args += ["--methods", "explicit_euler,semi_implicit_euler,rk4,dopri5", "--tol", "1e-4,1e-6,1e-8"]
    acc = cli_csv(binary, *args)
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for method, rows in acc.groupby("method", sort=False):
        rows = rows.sort_values("force_evaluations")
        ax.loglog(rows.force_evaluations, rows.position_error_m, "o-", label=method)
    ax.set_xlabel("force evaluations")
    ax.set_ylabel("end-point position error (m)")
    ax.set_title("Work-precision diagram")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    plt.close(fig)


OUTCOME_COLOURS = {"stable": "#4caf50", "energy_growth": "#ff9800", "nan": "#f44336", "escaped": "#9c27b0",
                   "jitter": "#2196f3", "tunnelled": "#795548"}


def plot_stability_map(binary, quick, path):
    cells = cli_csv(binary, "stability", *(["--quick"] if quick else []), "--csv")
    cells = cells[cells.slice == "map"]
    methods = list(dict.fromkeys(cells.method))
    columns = min(3, len(methods))
    rows_n = (len(methods) + columns - 1) // columns
    fig, axes = plt.subplots(rows_n, columns, figsize=(4 * columns, 3.2 * rows_n), squeeze=False, sharex=True, sharey=True)
    for ax, method in zip(axes.flat, methods):
        for outcome, group in cells[cells.method == method].groupby("outcome"):
            k = group.k_per_s.where(group.k_per_s > 0, 0.1)  # k = 0 (no drag) drawn at the left edge
            ax.scatter(k, group.dt_s, c=OUTCOME_COLOURS.get(outcome, "black"), s=40, marker="s", label=outcome)
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_title(method, fontsize=9)
    for ax in axes.flat[len(methods):]:
        ax.axis("off")
    handles = {h.get_label(): h for ax in axes.flat for h in ax.collections}
    fig.legend(handles.values(), handles.keys(), loc="lower right", fontsize=8)
    fig.supxlabel("linear drag stiffness k = b/m (1/s; 0 drawn at 0.1)")
    fig.supylabel("dt (s)")
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    plt.close(fig)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--bin", help="the particle-lab binary")
    parser.add_argument("--presets", type=pathlib.Path, default=ROOT / "presets", help="the presets folder")
    parser.add_argument("--out", type=pathlib.Path, default=pathlib.Path("."), help="folder for the PNG files")
    parser.add_argument("--quick", action="store_true", help="shorter runs and smaller studies (seconds)")
    args = parser.parse_args()
    binary = args.bin or find_binary()
    args.out.mkdir(parents=True, exist_ok=True)
    plot_drag_models(binary, args.presets, args.quick, args.out / "drag_models.png")
    plot_work_precision(binary, args.presets, args.quick, args.out / "work_precision.png")
    plot_stability_map(binary, args.quick, args.out / "stability_map.png")
    for name in ("drag_models.png", "work_precision.png", "stability_map.png"):
        print(args.out / name)


if __name__ == "__main__":
    main()

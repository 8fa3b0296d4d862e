#!/usr/bin/python3
"""Plot a shock-tube result against the exact solution.

Usage: plotShockTube.py CASE_DIR
Reads CASE_DIR/postProcessing/riemannError/<latest time>/profile.dat (written
by riemannError) and writes CASE_DIR/shockTube.png: density, velocity and
pressure, computed (dots) and exact (line).
"""
import os
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

from neuronFsi import postProcessing


def main(case):
    try:
        latest, path = postProcessing.segments(
            case, "riemannError/profile.dat")[-1]
    except postProcessing.ColumnFileError as err:
        sys.exit(f"plotShockTube: {err}: run riemannError first")
    data = postProcessing.readTable(path).data()
    x = data[:, 0]
    fig, axes = plt.subplots(3, 1, figsize=(7, 8), sharex=True)
    labels = [("density [kg/m^3]", 1), ("velocity [m/s]", 3),
              ("pressure [Pa]", 5)]
    for ax, (label, col) in zip(axes, labels):
        ax.plot(x, data[:, col + 1], "k-", lw=1.2, label="exact")
        ax.plot(x, data[:, col], ".", ms=3, color="tab:red",
                label=f"rhoRiemannFoam, {len(x)} cells")
        ax.set_ylabel(label)
        ax.grid(alpha=0.3)
    axes[0].legend(loc="best", fontsize=8)
    axes[-1].set_xlabel("x [m]")
    axes[0].set_title(f"{os.path.basename(os.path.abspath(case))}, "
                      f"t = {float(latest):g} s")
    fig.tight_layout()
    out = os.path.join(case, "shockTube.png")
    fig.savefig(out, dpi=110)
    print(f"plotShockTube: wrote {out}")


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    main(sys.argv[1])

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

try:
    from neuronFsi import script
except ImportError:
    sys.exit("plotShockTube.py: error: the project's Python package neuronFsi "
             "is not found: source the project's etc/bashrc first")
script.guard()  # an input's error: one line, exit 1 (adv33)
from neuronFsi import postProcessing


def main(case):
    try:
        latest, path = postProcessing.segments(
            case, "riemannError/profile.dat")[-1]
    except postProcessing.ColumnFileError as err:
        sys.exit(f"plotShockTube: {err}: run riemannError first")
    data = postProcessing.readTable(path).data()
    # the whole tube: as many rows as errors.dat (written with it) has
    # cells (adv33 sh24: a cut profile plotted as the whole, exit 0)
    errors = os.path.join(os.path.dirname(path), "errors.dat")
    nCells = postProcessing.readTable(errors).column("nCells")
    if len(nCells) != 1 or nCells[0] != len(data):
        sys.exit(f"plotShockTube.py: error: {path} holds {len(data)} rows,"
                 f" but {errors} (written with it) counts "
                 f"{' '.join('%g' % n for n in nCells)} cells: the profile "
                 "is cut or not of this run; run riemannError again")
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
    script.saveFigure(fig, out, dpi=110)
    print(f"plotShockTube: wrote {out}")


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    main(sys.argv[1])

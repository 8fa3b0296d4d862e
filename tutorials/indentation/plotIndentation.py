#!/usr/bin/python3
"""Plots and results table of a cellIndentationFoam case.

usage: plotIndentation.py <case> [<case> ...]

Reads <case>/postProcessing/indentation/{force,peaks}.dat and writes
<case>/indentation.png (force vs depth for each rate, like the paper's
Figs. 4-6, and force vs time) and <case>/results.md (the nine cycle peaks
next to the paper's Table 3, whose "mN" are nN, and F at the end of B and
on the E plateau next to the paper's 0.3 nN and 1.67 nN).
"""
import os
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

from neuronFsi import postProcessing

# Jerusalem & Dao 2012, Table 3 (validation cell 14.2 x 7.6 um) [nN]
PAPER_EXP = [11.5, 10.8, 10.3, 5.0, 4.9, 4.8, 3.0, 3.0, 3.0]
PAPER_SIM = [11.5, 11.0, 10.2, 5.3, 4.6, 4.3, 2.5, 2.5, 2.5]
PAPER_FB, PAPER_FE = 0.3, 1.67   # average cell, sec. 3.1 [nN]
RATES = {"C1": "10 um/s", "C2": "1 um/s", "C3": "0.1 um/s"}


def read(case):
    d = os.path.join(case, "postProcessing", "indentation")
    f = postProcessing.readTable(os.path.join(d, "force.dat"))
    rows = list(zip(f.column("time"), f.column("depth"), f.column("force"),
                    f.column("stage")))
    p = postProcessing.readTable(os.path.join(d, "peaks.dat"))
    peaks = {label: (t, z, F) for label, t, z, F in zip(
        p.column("label"), p.column("time"), p.column("depth"),
        p.column("force"))}
    return rows, peaks


def plot(case, rows, peaks):
    fig, ax = plt.subplots(1, 4, figsize=(17, 4))
    for k, stage in enumerate(["C1", "C2", "C3"]):
        # the cycles of a rate start from the preceding hold's depth
        z = [r[1]*1e6 for r in rows if r[3] == stage]
        F = [r[2]*1e9 for r in rows if r[3] == stage]
        ax[k].plot(z, F, "-")
        ax[k].set_title(f"{stage}: {RATES[stage]}")
        ax[k].set_xlabel("indenter depth [um]")
        ax[k].set_ylabel("force [nN]")
        ax[k].grid(True)
    ax[3].plot([r[0] for r in rows], [r[2]*1e9 for r in rows], "-")
    ax[3].set_xlabel("time [s]")
    ax[3].set_ylabel("force [nN]")
    ax[3].set_xscale("symlog", linthresh=30)
    ax[3].grid(True)
    fig.suptitle(os.path.basename(os.path.abspath(case)))
    fig.tight_layout()
    fig.savefig(os.path.join(case, "indentation.png"), dpi=110)


def table(case, peaks):
    labels = [f"C{a},{b}" for a in (1, 2, 3) for b in ("i", "ii", "iii")]
    out = ["| quantity | this run [nN] | paper exp. [nN] | paper sim. [nN] |",
           "|---|---|---|---|"] if "validation" in os.path.abspath(case) else \
          ["| quantity | this run [nN] | paper exp., validation cell [nN] "
           "| paper sim., validation cell [nN] |",
           "|---|---|---|---|"]
    for k, label in enumerate(labels):
        F = peaks.get(label, (0, 0, float("nan")))[2]*1e9
        out.append(f"| {label} | {F:.3g} | {PAPER_EXP[k]} | {PAPER_SIM[k]} |")
    FB = peaks.get("endB", (0, 0, float("nan")))[2]*1e9
    FE = peaks.get("endE", (0, 0, float("nan")))[2]*1e9
    out.append(f"| F_B (end of B) | {FB:.3g} | {PAPER_FB} (average cell) | |")
    out.append(f"| F_E (end of E) | {FE:.3g} | {PAPER_FE} (average cell) | |")
    text = "\n".join(out) + "\n"
    with open(os.path.join(case, "results.md"), "w") as f:
        f.write(text)
    print(text)


for case in sys.argv[1:] or ["."]:
    try:
        rows, peaks = read(case)
    except postProcessing.ColumnFileError as err:
        # the file and line named, no traceback (adv30 pp02, pp05)
        sys.exit(f"plotIndentation.py: {err}")
    plot(case, rows, peaks)
    table(case, peaks)

#!/usr/bin/python3
"""Solid subcycling on the blast preview with a refined solid (not a test).

Issue 18 item 4: copies of tutorials/blast/axisymmetricPreview
(tests/blast/runPreview.sh) with solid elements of --cell (0.25 um: the
solid's stable step below the fluid's Courant step) and the fluid at the
cell at half of it (-h: cellBlastFoam refuses a solid interface finer
than the fluid's since issue 17's unseen-modes check), the short column
(-Z 30e-6) to --endTime, for each --subcycles N (coupling{}
solidSubcycles), one run after another. Per N: coupled steps, coupling
passes per step, solid steps (the solver's count at the last write
time), CPU of the time loop (cellBlastFoam's
closing line) and its solid share, the peaks of the Fig. 10 solid probe
(pressure, von Mises) and of the fluid probes' pressure, the interface
energies at the end (the fluid's work on its wall and the solid's
external work, coupling.dat's last columns), their relative difference
at the end and their largest difference over the run relative to the
largest work, and each peak's difference to the first N.

    bench/blast/subcycles.py [--out DIR] [--subcycles "1 4"]
        [--cell 0.25e-6] [--endTime 3e-8] [--reportOnly]

Prints a markdown table (docs/userGuide/fsi.md, docs/benchmarks.md).
"""
import argparse
import os
import re
import subprocess
import sys

import numpy as np

from neuronFsi import script  # noqa: E402
script.guard()  # an input's error: one line, exit 1 (fix19k: every script)
from neuronFsi import bench, logs, postProcessing

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", ".."))


def run(out, n, cell, endTime):
    d = os.path.join(out, f"N{n}")
    subprocess.run(["bash", os.path.join(ROOT, "tests", "blast",
                                         "runPreview.sh"), d, "-noPlots",
                    "-cell", str(cell), "-h", str(cell/2), "-Z", "30e-6",
                    "-endTime",
                    str(endTime), "-solidSubcycles", str(n)],
                   check=True, stdout=subprocess.DEVNULL)
    return os.path.join(d, "axisymmetricPreview")


def measure(case):
    log = os.path.join(case, "log.cellBlastFoam")
    c = postProcessing.series(case, "fsi/coupling.dat")
    cpu = logs.search(log, r"^CPU time of the time loop (\S+) s: mesh motion "
                      r"\S+ s, fluid \S+ s, solid (\S+) s", "CPU split",
                      last=True)
    solidSteps = int(logs.search(log, r"^Solid: energy balance .* (\d+) "
                                 r"steps$", "solid steps", last=True)[0])
    energy = float(logs.search(log, r"^FSI interface energy: .* relative "
                               r"difference (\S+)", "interface energy",
                               last=True)[0])
    p = postProcessing.series(case, "solidProbes/solidProbes.dat")
    fp = postProcessing.readTable(os.path.join(
        case, "postProcessing", "fluidProbes", "0", "p")).data()
    return dict(steps=len(c), passes=c[:, 2].mean(), dtMax=c[:, 1].max(),
                solidSteps=solidSteps, cpu=float(cpu[0]),
                cpuSolid=float(cpu[1]), pMax=p[:, 1].max(),
                vmMax=p[:, 2].max(), fluidMax=fp[:, 1:].max(axis=0),
                fluidWork=c[-1, 10], solidWork=c[-1, 11], energy=energy,
                energyMax=np.abs(c[:, 10] - c[:, 11]).max()
                / np.abs(c[:, 11]).max())


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", default="/tmp/subcycles")
    ap.add_argument("--subcycles", default="1 4")
    ap.add_argument("--cell", type=float, default=0.25e-6)
    ap.add_argument("--endTime", type=float, default=3e-8)
    ap.add_argument("--reportOnly", action="store_true",
                    help="measure the runs already in --out")
    a = bench.parse(ap)
    ns = [int(n) for n in a.subcycles.split()]
    cases = [os.path.join(a.out, f"N{n}", "axisymmetricPreview")
             if a.reportOnly else run(a.out, n, a.cell, a.endTime)
             for n in ns]
    rows = [(n, measure(c)) for n, c in zip(ns, cases)]
    ref = rows[0][1]
    rel = lambda x, y: 100*np.max(np.abs(x - y)/np.abs(y))
    signed = lambda x, y: 100*(x - y)/y
    print(f"Preview, solid {a.cell:g} m, column 30 um, to "
          f"{a.endTime:g} s (bench/blast/subcycles.py --cell {a.cell:g} "
          f"--endTime {a.endTime:g} --subcycles \"{a.subcycles}\")\n")
    print("| solidSubcycles | coupled steps | largest dt [s] | passes/step "
          "| solid steps (last write) | CPU time loop [s] | solid [s] | probe p peak "
          "[MPa] | probe von Mises peak [Pa] | fluid probes' peaks, largest "
          "difference [%] | interface work fluid / solid at the end [J] | "
          "relative difference at the end [-] | largest difference over "
          "the run / largest work [-] |")
    print("|" + " --- |"*13)
    for n, r in rows:
        print(f"| {n} | {r['steps']} | {r['dtMax']:.3e} | {r['passes']:.2f} "
              f"| {r['solidSteps']} | {r['cpu']:.1f} | {r['cpuSolid']:.1f} "
              f"| {r['pMax']/1e6:.3f} ({signed(r['pMax'], ref['pMax']):+.2f} %)"
              f" | {r['vmMax']:.2f} ({signed(r['vmMax'], ref['vmMax']):+.2f} %)"
              f" | {rel(r['fluidMax'], ref['fluidMax']):.3f} "
              f"| {r['fluidWork']:.4e} / {r['solidWork']:.4e} "
              f"| {r['energy']:.2e} | {r['energyMax']:.2e} |")
    return 0


if __name__ == "__main__":
    sys.exit(bench.main(main))

#!/usr/bin/python3
"""Two runs of the blast preview side by side (issue 18 item 5, branch
prev18; not a test): coupled steps, coupling passes per step, the CPU
split of the time loop (cellBlastFoam's closing line; CPU times under
load are noise, the passes are not), and how far the second run's
results are from the first's:

  - per column of postProcessing/fluidProbes/0/p (the water probes),
    solidProbes/solidProbes.dat (the Fig. 10 probe: pressure, von Mises,
    strains, ...) and solidInterfaces/interfaceMaxima.dat: the largest
    difference over the run, the second run's rows interpolated
    linearly in time to the first's times, relative to the first run's
    range of that column (max - min); the worst column of each file
    named;
  - the peaks of the water probes' pressure and of the Fig. 10 probe's
    pressure and von Mises, and their relative differences.

    bench/blast/compareRuns.py REF NEW [--after T0]

REF, NEW: the cases (e.g. DIR/axisymmetricPreview of
tests/blast/runPreview.sh DIR ...), finished or not: their common time
span is compared. --after T0 [s]: only rows at t >= T0 (e.g. the passage
of the pulse). Prints markdown (docs/benchmarks.md).
"""
import argparse
import os
import sys

import numpy as np

from neuronFsi import script  # noqa: E402
script.guard()  # an input's error: one line, exit 1 (fix19k: every script)
from neuronFsi import bench, logs, postProcessing


def table(case, log):
    return postProcessing.series(case, log)


def compare(ref, new, after, label):
    """(worst relative difference, worst column name) of two tables over
    their common times (new interpolated to ref's times)"""
    t0 = max(ref[0, 0], new[0, 0], after)
    t1 = min(ref[-1, 0], new[-1, 0])
    keep = (ref[:, 0] >= t0) & (ref[:, 0] <= t1)
    r = ref[keep]
    worst, where = 0.0, None
    common = label.startswith("coupling.dat")
    for j in range(1, ref.shape[1]):
        # the force's components against the largest component range (the
        # wedge's out-of-plane component is round-off)
        span = np.ptp(r[:, 1:], axis=0).max() if common else np.ptp(r[:, j])
        if span == 0:
            continue
        n = np.interp(r[:, 0], new[:, 0], new[:, j])
        d = np.max(np.abs(n - r[:, j]))/span
        if d > worst:
            k = np.argmax(np.abs(n - r[:, j]))
            worst, where = d, f"{label} column {j} at t = {r[k, 0]:.4g} s"
    return worst, where, t1


def peaks(case, after, end):
    p = table(case, "fluidProbes/p")
    s = table(case, "solidProbes/solidProbes.dat")
    p = p[(p[:, 0] >= after) & (p[:, 0] <= end)]
    s = s[(s[:, 0] >= after) & (s[:, 0] <= end)]
    return p[:, 1:].max(axis=0), s[:, 1].max(), s[:, 2].max()


def cpu(case):
    log = os.path.join(case, "log.cellBlastFoam")
    if not os.path.exists(log):
        return "(no log.cellBlastFoam: run stopped)"
    line = logs.cpuSplit(log)
    return line if line else "(run not finished)"


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("ref")
    ap.add_argument("new")
    ap.add_argument("--after", type=float, default=0.0)
    a = bench.parse(ap)
    rows = []
    ends = [table(case, "fsi/coupling.dat")[-1, 0]
            for case in (a.ref, a.new)]
    for case in (a.ref, a.new):
        c = table(case, "fsi/coupling.dat")
        c = c[(c[:, 0] >= a.after) & (c[:, 0] <= min(ends))]
        rows.append((case, len(c), c[:, 2].sum(), c[-1, 0]))
    print(f"Runs compared (bench/blast/compareRuns.py {a.ref} {a.new}"
          f" --after {a.after:g}):\n")
    print("| run | coupled steps | passes | passes/step | to t [s] (common span) | "
          "CPU split of the time loop |")
    print("|---|---:|---:|---:|---:|---|")
    for case, n, passes, t in rows:
        print(f"| {case} | {n} | {passes:.0f} | {passes/max(n, 1):.3f} | "
              f"{t:.4g} | {cpu(case)} |")
    print()
    print("| log | largest difference / REF's range | column | common span"
          " to [s] |")
    print("|---|---:|---|---:|")
    for log, label in (("fluidProbes/p", "fluidProbes p"),
                       ("solidProbes/solidProbes.dat", "solidProbes"),
                       ("solidInterfaces/interfaceMaxima.dat",
                        "interfaceMaxima"),
                       ("fsi/coupling.dat", "coupling.dat")):
        if log == "fsi/coupling.dat":
            # the force (columns 5-7) only: the passes and residuals differ
            # by construction
            r = table(a.ref, log)[:, [0, 5, 6, 7]]
            n = table(a.new, log)[:, [0, 5, 6, 7]]
            label = "coupling.dat interface force (x y z)"
        else:
            r, n = table(a.ref, log), table(a.new, log)
        d, where, t1 = compare(r, n, a.after, label)
        print(f"| {log} | {d:.2e} | {where} | {t1:.4g} |")
    end = min(rows[0][3], rows[1][3])
    pr, sr, vr = peaks(a.ref, a.after, end)
    pn, sn, vn = peaks(a.new, a.after, end)
    print()
    print("Peaks over the common rows (REF -> NEW): water probes "
          + ", ".join(f"{x/1e6:.4f} -> {y/1e6:.4f} MPa ({100*(y - x)/x:+.3f} %)"
                      for x, y in zip(pr, pn))
          + f"; Fig. 10 probe pressure {sr/1e6:.4f} -> {sn/1e6:.4f} MPa "
          f"({100*(sn - sr)/sr:+.3f} %), von Mises {vr:.4f} -> {vn:.4f} Pa "
          f"({100*(vn - vr)/vr:+.3f} %)")
    return 0


if __name__ == "__main__":
    sys.exit(bench.main(main))

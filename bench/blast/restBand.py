#!/usr/bin/python3
"""The after-pulse state of blast cases side by side (issue 17 item 6 and
the mesh-motion band's width): for each CASE (a run of the preview or of
the quarter, its postProcessing written) the Fig. 10 probes' rest measures
as planeWave -check computes them (neuronFsi.planeWave.solidMeasures: the
largest von Mises after 140 ns over its largest 1-ns mean, the largest
|strain_z| after 140 ns), the probe's von Mises at fixed times, its growth
rate over the last 40 ns, and the interface patches' von Mises after the
pulse (interfacePatches.dat, the 1-um patch means and the element maxima
of issue 17 item 5). With two or more cases, each column's difference
from the first case relative to the first case's range over the run.
Not a test (docs/results/blast3D.md, "What keeps the 3D cell flowing").

    bench/blast/restBand.py CASE [CASE ...] [--times 8e-8 1e-7 ...]
"""
import argparse
import os

import numpy as np

from neuronFsi import script  # noqa: E402
# an input's error is one line, not a traceback (adv52 p18)
script.guard()
from neuronFsi import planeWave, postProcessing

PROBES = "solidProbes/solidProbes.dat"
PATCHES = "solidInterfaces/interfacePatches.dat"


def at(t, v, times):
    """v interpolated at each of times (a run's last step may end up to
    0.1 ns before its endTime: its last value there; nan beyond)."""
    return [float(np.interp(x, t, v)) if t[0] <= x <= t[-1] + 1e-10
            else np.nan for x in times]


def caseData(case, times):
    out = {}
    d = postProcessing.series(case, PROBES)
    cols = postProcessing.names(case, PROBES)
    t = d[:, 0]
    for i in (0, 1):
        vm = d[:, cols.index("vonMises%d" % i)]
        ez = d[:, cols.index("strainZ%d" % i)]
        s, _ = planeWave.solidMeasures(t, vm, ez, t, vm, ez)
        late = t >= t[-1] - 40e-9
        slope = np.polyfit(t[late], vm[late], 1)[0]
        out["probe%d" % i] = dict(
            # None: the run ends before 145 ns (still running)
            rest=(s["restVonMises"]/s["vonMises1ns"]
                  if s["restVonMises"] is not None else np.nan),
            restVM=(s["restVonMises"] if s["restVonMises"] is not None
                    else np.nan), peak=s["vonMises1ns"],
            restStrain=(s["restStrain"] if s["restStrain"] is not None
                        else np.nan), slope=slope,
            vm=at(t, vm, times), t=t, series=vm)
    if os.path.isdir(os.path.join(case, "postProcessing", "solidInterfaces")):
        d = postProcessing.series(case, PATCHES)
        cols = postProcessing.names(case, PATCHES)
        for c in ("vonMisesPatch:membrane-cytoplasm",
                  "vonMisesPatch:cytoplasm-nucleus",
                  "vonMisesMax:membrane-cytoplasm",
                  "vonMisesMax:cytoplasm-nucleus"):
            out[c] = dict(vm=at(d[:, 0], d[:, cols.index(c)], times),
                          t=d[:, 0], series=d[:, cols.index(c)])
    return out


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("cases", nargs="+")
    p.add_argument("--times", type=float, nargs="+",
                   default=[8e-8, 9e-8, 1e-7, 1.2e-7, 1.36e-7, 1.5e-7])
    a = p.parse_args()
    data = [caseData(c, a.times) for c in a.cases]
    tt = "  ".join("%7.1f" % (x*1e9) for x in a.times)
    for i in (0, 1):
        side = ("cytoplasm", "nucleus")[i]
        print("Fig. 10 probe %d (%s side): rest von Mises / 1-ns peak, rest "
              "[Pa], peak [Pa], rest |strain_z|, growth over the last 40 ns "
              "[Pa/ns]; von Mises [Pa] at t [ns] = %s" % (i, side, tt))
        for c, d in zip(a.cases, data):
            q = d["probe%d" % i]
            print("  %-40s %.4f  %.3f  %.3f  %.2e  %+.4f | %s"
                  % (c[-40:], q["rest"], q["restVM"], q["peak"],
                     q["restStrain"], q["slope"]*1e-9,
                     "  ".join("%7.3f" % v for v in q["vm"])))
    for c in ("vonMisesPatch:membrane-cytoplasm",
              "vonMisesPatch:cytoplasm-nucleus",
              "vonMisesMax:membrane-cytoplasm",
              "vonMisesMax:cytoplasm-nucleus"):
        if not all(c in d for d in data):
            continue
        print("%s [Pa] at t [ns] = %s" % (c, tt))
        for case, d in zip(a.cases, data):
            print("  %-40s %s" % (case[-40:], "  ".join(
                "%7.3f" % v for v in d[c]["vm"])))
    if len(data) > 1:
        print("largest difference from the first case after 70 ns, "
              "relative to the first case's range over the run:")
        keys = [k for k in data[0] if all(k in d for d in data)]
        for case, d in zip(a.cases[1:], data[1:]):
            row = []
            for k in keys:
                t0, v0 = data[0][k]["t"], data[0][k]["series"]
                v = np.interp(t0, d[k]["t"], d[k]["series"])
                late = (t0 >= 70e-9) & (t0 <= min(t0[-1], d[k]["t"][-1]))
                rng = v0.max() - v0.min()
                row.append("%s %.3f" % (k.replace("vonMises", "vM"),
                                        np.abs(v - v0)[late].max()/rng))
            print("  %-40s %s" % (case[-40:], ", ".join(row)))


if __name__ == "__main__":
    main()

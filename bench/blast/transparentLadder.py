#!/usr/bin/env python3
"""The ladder table of bench/blast/transparentCell.sh runs (issue 17 item
1; docs/results/blastPlaneWave.md, "The transparent cell"; not a test).

Usage: transparentLadder.py [-layered] SCALE=DIR [SCALE=DIR ...]
       transparentLadder.py -item1 [-layered] LABEL=DIR [LABEL=DIR ...]

Each DIR a transparentCell.sh run (DIR/axisymmetricPreview after its
planeWave -check; with -layered its planeWave -check -layered), SCALE its
level (1, 0.7, 0.5, 0.35: the cell sizes are SCALE times x1's). Prints per
level the water cells (log.checkMesh), the time loop's CPU
(log.cellBlastFoam), the water probes' 1-ns peak error at each r (z =
10 um) and the solid probe's (p0, cytoplasm side) incident 1-ns peak,
1-ns peak, plateau and impulse errors [%]; then for each measure, from
the three finest levels, the observed order p and the Richardson limit
e0 of e(h) = e0 + C h^p, and the order assuming the limit 0 (ln(e2/e3) /
ln(h2/h3), the two finest levels).

With -item1 (docs/results/blastPlaneWave.md, "The cheapest default that
meets item 1"), one row per run LABEL in the order given: water cells,
solid elements (log.cellBlastFoam), the time loop's CPU, and issue 17
item 1's measures: the water probes' 1-ns peak error on the axis (r =
0.1 um) and at r = 4 um, the solid probe's (p0) incident 1-ns peak and
1-ns peak, and over every probe the largest |error| of the plateau, the
impulse [%] and the arrival [ns]; the solid probe's von Mises and
strain 1-ns peak errors, cytoplasm / nucleus side (solidMeasures.dat:
issue 17 items 4-6, which planeWave -check also bounds by 5 %); then the
measures outside the bounds (arrival 0.3 ns, peaks and plateau 5 %,
impulse 3 %, von Mises and strain 5 %; "-": none).
"""
import math
import os
import re
import sys

from neuronFsi import script  # noqa: E402
script.guard()  # an input's error: one line, exit 1 (adv53 u12)
from neuronFsi import convergence, planeWave


def byProbe(case, sub, name):
    """planeWave's measures.dat or solidMeasures.dat of the case as
    {probe: row} (neuronFsi.planeWave.readMeasures: rows by column name)"""
    return {r["probe"]: r for r in planeWave.readMeasures(
        os.path.join(case, "postProcessing", sub, "0", name))}


def level(arg, layered):
    scale, d = script.labelled(arg, "SCALE=CASE")
    case = os.path.join(d, "axisymmetricPreview")
    sub = "planeWaveLayered" if layered else "planeWave"
    m = byProbe(case, sub, "measures.dat")
    cells = re.search(r"^\s*cells:\s+(\d+)", open(os.path.join(
        case, "log.checkMesh")).read(), re.M).group(1)
    cpu = re.search(r"^CPU time of the time loop ([0-9.e+-]+) s", open(
        os.path.join(case, "log.cellBlastFoam")).read(), re.M).group(1)
    out = {"h": float(scale), "cells": int(cells), "cpu": float(cpu)}
    # the water probes: r from system/controlDict.allrun's list
    probes = re.findall(r"\(([0-9.e+-]+) ([0-9.e+-]+) 0\)", open(os.path.join(
        case, "system", "controlDict.allrun")).read())
    for i, (r, z) in enumerate(probes):
        out["water r=%g um" % (float(r)*1e6)] = \
            m["fluidProbes_%d" % i]["errPeak1ns"]
    s = m["solid_p0"]
    for name, col in (("solid incident", "errPeakIncident"),
                      ("solid 1-ns peak", "errPeak1ns"),
                      ("solid plateau", "errPlateau"),
                      ("solid impulse", "errImpulse")):
        out[name] = s[col]
    return out


BOUNDS = {"peak1ns": 5.0, "peakIncident": 5.0, "plateau": 5.0,
          "impulse": 3.0, "arrival": 0.3}
COLUMNS = {"arrival": "errArrival", "peak1ns": "errPeak1ns",
           "peakIncident": "errPeakIncident", "plateau": "errPlateau",
           "impulse": "errImpulse"}


def item1(arg, layered):
    """One row of the -item1 table (see the module text)"""
    label, d = script.labelled(arg, "LABEL=CASE")
    case = os.path.join(d, "axisymmetricPreview")
    sub = "planeWaveLayered" if layered else "planeWave"
    m = byProbe(case, sub, "measures.dat")
    log = open(os.path.join(case, "log.cellBlastFoam")).read()
    cells = re.search(r"^\s*cells:\s+(\d+)", open(os.path.join(
        case, "log.checkMesh")).read(), re.M).group(1)
    elements = re.search(r"^Solid: (\d+) elements", log, re.M).group(1)
    cpu = re.search(r"^CPU time of the time loop ([0-9.e+-]+) s", log,
                    re.M).group(1)
    # the probes as the solver reads them: controlDict.allrun's list
    # if it gives one, else controlDict's (adv54 n29: the preview's
    # probes are in controlDict itself)
    probes = []
    for name in ("controlDict.allrun", "controlDict"):
        path = os.path.join(case, "system", name)
        if not probes and os.path.isfile(path):
            probes = re.findall(r"\(([0-9.e+-]+) ([0-9.e+-]+) 0\)",
                                open(path).read())
    water = {float(r): "fluidProbes_%d" % i for i, (r, z) in enumerate(probes)}

    def err(name, key):
        v = m[name][COLUMNS[key]]
        return None if v == "-" else v
    out = [label, cells, elements, "%.1f" % float(cpu)]
    for r in (1e-7, 4e-6):
        # the probe at that radius, as printed in controlDict.allrun
        # (9.9999999999999995e-08 for 1e-7: adv54 n29's KeyError)
        near = [q for q in water if abs(q - r) <= 1e-9*r]
        if not near:
            sys.exit("transparentLadder.py: error: %s: no water probe at r = "
                     "%g m among the fluidProbes of system/controlDict(.allrun)"
                     " (radii %s)" % (case, r, ", ".join(
                         "%g" % q for q in sorted(water))))
        out.append("%+.2f %%" % err(water[near[0]], "peak1ns"))
    worst = max((abs(err(n, "peak1ns")), r) for r, n in water.items())
    out.append("%+.2f %% (%g um)" % (err(water[worst[1]], "peak1ns"),
                                     worst[1]*1e6))
    out.append("%+.2f %%" % err("solid_p0", "peakIncident"))
    out.append("%+.2f %%" % err("solid_p0", "peak1ns"))
    fails = []
    for key in ("plateau", "impulse", "arrival"):
        e = [(abs(err(n, key)), n) for n in m if err(n, key) is not None]
        worst = max(e)
        out.append(("%.3f ns" if key == "arrival" else "%.2f %%") % worst[0])
    solid = byProbe(case, sub, "solidMeasures.dat")
    for col, key in (("errVonMises", "vonMises1ns"),
                     ("errStrain", "strain1ns")):
        out.append(" / ".join("%+.2f %%" % solid[n][col]
                              for n in ("solid_0", "solid_1")))
        for n in ("solid_0", "solid_1"):
            if abs(solid[n][col]) > 5.0:
                fails.append("%s (%s) %s %+.2f" % (n.replace("_", " "),
                             solid[n]["region"], key, solid[n][col]))
    names = {v: "water r = %g um" % (r*1e6) for r, v in water.items()}
    for n in m:
        # solid p2 (the cytoplasm side named) repeats p0 (the same side)
        if n == "solid_p2" and {k: v for k, v in m[n].items()
                                if k not in ("probe", "z")} == {
                k: v for k, v in m.get("solid_p0", {}).items()
                if k not in ("probe", "z")}:
            continue
        for key, bound in BOUNDS.items():
            e = err(n, key)
            if e is not None and abs(e) > bound:
                fails.append("%s %s %+.2f" % (names.get(n, n.replace(
                    "_", " ")), key, e))
    out.append("; ".join(fails) or "-")
    return out


def item1Table(args, layered):
    print("| setting | water cells | solid elements | CPU time loop to "
          "its end [s] | water 1-ns peak r = 0.1 um | r = 4 um | worst (r) | solid "
          "incident 1-ns peak | solid 1-ns peak | plateau (worst) | impulse "
          "(worst) | arrival (worst) | solid von Mises 1-ns peak, "
          "cytoplasm / nucleus | solid strain 1-ns peak | outside the "
          "bounds |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
          "---:|---|")
    for a in args:
        print("| " + " | ".join(item1(a, layered)) + " |")


def main():
    args = sys.argv[1:]
    layered = "-layered" in args
    table1 = "-item1" in args
    args = [a for a in args if a not in ("-layered", "-item1")]
    if not args:
        sys.exit(__doc__)
    if table1:
        item1Table(args, layered)
        return
    levels = sorted((level(a, layered) for a in args), key=lambda x: -x["h"])
    keys = [k for k in levels[0] if k not in ("h", "cells", "cpu")]
    print("| level | water cells | CPU time loop [s] | "
          + " | ".join(keys) + " |")
    print("|---|---:|---:|" + "---:|"*len(keys))
    for lv in levels:
        print("| x%g | %d | %.1f | " % (lv["h"], lv["cells"], lv["cpu"])
              + " | ".join("%+.2f %%" % lv[k] for k in keys) + " |")
    if len(levels) >= 3:
        h = [lv["h"] for lv in levels[-3:]]
        cells = []
        for k in keys:
            e = [lv[k] for lv in levels[-3:]]
            c = convergence.threeLevel(h, e)
            e0, p = c.extrapolated, c.p
            p0 = (math.log(e[1]/e[2])/math.log(h[1]/h[2])
                  if e[1]*e[2] > 0 else float("nan"))
            cells.append("p %s, e0 %s; p(e0 = 0) %.2f" % (
                "-" if p is None else "%.2f" % p,
                "-" if e0 is None else "%+.2f %%" % e0, p0))
        print("| order, limit (x%g, x%g, x%g) | | | " % tuple(h)
              + " | ".join(cells) + " |")


if __name__ == "__main__":
    main()

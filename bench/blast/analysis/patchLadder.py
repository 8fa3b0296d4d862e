#!/usr/bin/python3
"""The blast preview's measures on a mesh ladder, with observed orders,
Richardson estimates and error bars (issue 17 items 4 and 5; not a test).

    patchLadder.py [--pulse P] [--t1 T1] [--default LABEL]
                   [--ifWindow W] LABEL=CASE ... [--off LABEL=CASE ...]

LABEL: x<f> or x<f>L<n> (f the Allrun's size factor, every size scaled by
it; n the membrane's layers, -membraneLayers: a label only). --off:
settings that are not a level of the ladder (e.g. another default's
sizes), compared with the ladder's Richardson value only.

Per case, the largest over the passage (t <= 80 ns + P, P the pulse [s],
default 1.5e-8; or t <= T1 [ns]) of:
- the Fig. 10 point's probes (solidProbes.dat, one per region: cytoplasm
  and nucleus side): the 1-ns running means (planeWave.runningMean, as
  planeWave and bench/blast/run.py) of pressure, von Mises, the
  longitudinal strain ln(stretch_z) and its rate (most negative for the
  two strains: compression);
- per interface (interfacePatches.dat, every step): the largest mean over
  the fixed patch length of von Mises and shear (the largest over
  places) and the element maxima (mesh-dependent);
- per interface and fixed place (interfacePlaces.dat, when the run wrote
  it): the mean of von Mises and shear over the patch at that place.
With --ifWindow W [ns] the interface series are first averaged over a
running window of W (planeWave.runningMean, as the probes' 1 ns) before
their largest value is taken: whether a measure without an order has one
once its fastest part in time is averaged out (the probes are 1-ns means,
the interface measures otherwise instantaneous).
Then the change from level to level, and from the three finest levels the
observed order p, the Richardson value and the finest level's Grid
Convergence Index (bench/blast/run.py richardson: Celik et al. 2008 for
non-constant ratios; no order where the changes alternate in sign or do
not shrink: then "no order" and the error bar is 3 times the largest
change; each level's deviation from the Richardson value; an order above 2, the scheme's formal order, is flagged
unreliable: the ratio of two changes of which the first is large, not an
asymptotic order), with the deviation of --default (default x0.7) and of each --off
setting from the Richardson value. With four levels or more the order
from the three coarsest too (a stable order is the sign of the asymptotic
range). Prints markdown tables.
"""
import argparse
import importlib.machinery
import importlib.util
import os
import re

import numpy as np

from neuronFsi import script  # noqa: E402
script.guard()  # an input's error: one line, exit 1 (fix19k: every script)
from neuronFsi import damageIndicators, planeWave, postProcessing

HERE = os.path.dirname(os.path.abspath(__file__))
_loader = importlib.machinery.SourceFileLoader(
    "blastRun", os.path.join(HERE, "..", "run.py"))
_spec = importlib.util.spec_from_loader("blastRun", _loader)
R = importlib.util.module_from_spec(_spec)
_loader.exec_module(R)

INTERFACES = ("membrane-cytoplasm", "cytoplasm-nucleus", "membrane-fluid")
QUANTITIES = (("vonMisesPatch", "von Mises, largest 1-um mean"),
              ("shearPatch", "shear, largest 1-um mean"),
              ("vonMisesMax", "von Mises element max"),
              ("shearMax", "shear element max"))
PLACE_QUANTITIES = (("vonMisesAt", "von Mises"), ("shearAt", "shear"))
WINDOW = 1e-9       # [s] the probes' running means
PROBE = (("p", "pressure 1-ns peak [MPa]", 1e-6, max),
         ("vonMises", "von Mises 1-ns peak [Pa]", 1.0, max),
         ("strainZ", "strain_z 1-ns peak [-]", 1.0, min),
         ("strainRateZ", "strain rate 1-ns peak [1/s]", 1.0, min))


def factor(label):
    m = re.match(r"x([0-9.]+)(L\d+)?$", label)
    if not m:
        raise SystemExit(f"patchLadder: label {label!r}: x<factor> or "
                         "x<factor>L<layers>")
    return float(m.group(1))


def probeMeasures(case, t1, out):
    """The 1-ns peaks of the first probe of each region (the Fig. 10
    point's cytoplasm and nucleus sides)"""
    pf = "solidProbes/solidProbes.dat"
    probes = postProcessing.probes(case, pf)
    d = postProcessing.series(case, pf)
    n = len(probes)
    t = d[:, 0]
    seen = set()
    for i, pr in enumerate(probes):
        if pr["region"] in seen:
            continue
        seen.add(pr["region"])
        cols = {"p": 1 + 5*i, "vonMises": 2 + 5*i,
                "strainZ": 1 + 5*n + 2*i, "strainRateZ": 2 + 5*n + 2*i}
        for q, _, scale, pick in PROBE:
            tc, m = planeWave.runningMean(t, d[:, cols[q]], WINDOW)
            out[f"probe:{pr['region']}:{q}"] = scale*pick(m[tc <= t1])


def averaged(t, y, window):
    """(t, y) as they are (window 0) or their running mean over window
    [s] (planeWave.runningMean: the samples whose window lies inside)"""
    return (t, y) if not window else planeWave.runningMean(t, y, window)


def level(label, case, t1, window=0.0):
    """The measures of one case; window [s]: the interface series'
    running mean before their maximum (0: instantaneous)"""
    out = {"factor": factor(label), "label": label}
    probeMeasures(case, t1, out)
    ip = damageIndicators.interfacePatches(case)
    for n in INTERFACES:
        if n not in ip:
            continue
        d = ip[n]
        for q, _ in QUANTITIES:
            t, y = averaged(d["t"], d[q], window)
            out[f"{q}:{n}"] = y[t <= t1].max()
        # the place of the instantaneous largest mean
        w = d["t"] <= t1
        k = np.argmax(np.where(w, d["vonMisesPatch"], -np.inf))
        out[f"at:{n}"] = (d["vonMisesPatchX"][k], d["vonMisesPatchY"][k],
                          d["t"][k])
    if damageIndicators.hasInterfacePlaces(case):
        for n, places in damageIndicators.interfacePlaces(case).items():
            for pl, d in places.items():
                for q, _ in PLACE_QUANTITIES:
                    t, y = averaged(d["t"], d[q], window)
                    w = t <= t1
                    out[f"{q}_{pl}:{n}"] = y[w].max()
                    if q == "vonMisesAt":
                        out[f"when_{pl}:{n}"] = t[np.argmax(
                            np.where(w, y, -np.inf))]
                out[f"centre_{pl}:{n}"] = d.get("centre")
    return out


def fmt(v):
    a = abs(v)
    if a == 0:
        return "0"
    if a >= 1e4 or a < 1e-2:
        return "%.4g" % v
    return "%.2f" % v if a >= 10 else "%.4g" % v


def row(name, key, levels, default, off):
    vals = [r[key] for r in levels]
    ch = " / ".join("%+.1f %%" % (100*(b/a - 1)) for a, b in
                    zip(vals, vals[1:]))
    order = ext = gci = dev = coarse = "-"
    offs = []
    if len(levels) >= 3:
        res = R.richardson(levels, key)
        if res["monotone"]:
            # above the scheme's formal order (2): the ratio of two
            # changes of which the first is large, not an asymptotic order
            order = "%.2f" % res["p"] + (" (> 2: unreliable)"
                                          if res["p"] > 2 else "")
            ext = fmt(res["ext"])
            gci = "%.1f %%" % (100*res["gci"])
            dev = ", ".join(
                ("**%s %+.1f %%**" if r["label"] == default else
                 "%s %+.1f %%") % (r["label"], 100*(r[key]/res["ext"] - 1))
                for r in levels)
            offs = ["%s %s (%+.1f %%)" % (o["label"], fmt(o[key]),
                                          100*(o[key]/res["ext"] - 1))
                    for o in off if key in o]
        else:
            order = "no order"
            gci = "(%.1f %%)" % (100*res["gci"])
            offs = ["%s %s" % (o["label"], fmt(o[key])) for o in off
                    if key in o]
        if len(levels) >= 4:
            res3 = R.richardson(levels[:3], key)
            coarse = "%.2f" % res3["p"] if res3["monotone"] else "none"
    return (f"| {name} | " + " | ".join(fmt(v) for v in vals)
            + f" | {ch} | {coarse} | {order} | {ext} | {gci} | {dev} | "
            + ("; ".join(offs) if offs else "-") + " |")


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--pulse", type=float, default=1.5e-8)
    ap.add_argument("--t1", type=float, default=None,
                    help="end of the window [ns] (default 80 ns + pulse)")
    ap.add_argument("--default", default="x0.7",
                    help="the level whose error is reported")
    ap.add_argument("--off", action="append", default=[],
                    help="LABEL=CASE of a setting off the ladder")
    ap.add_argument("--ifWindow", type=float, default=0.0,
                    help="running window [ns] of the interface series "
                    "before their maximum (default 0: instantaneous)")
    ap.add_argument("cases", nargs="+")
    a = ap.parse_args()
    if not 0 <= a.ifWindow < 100:
        raise SystemExit(f"patchLadder: --ifWindow {a.ifWindow:g}: a window "
                         "[ns] in [0, 100)")
    t1 = a.t1*1e-9 if a.t1 is not None else 80e-9 + a.pulse
    win = a.ifWindow*1e-9
    levels = sorted((level(*c.split("=", 1), t1, win) for c in a.cases),
                    key=lambda r: -r["factor"])
    off = []
    for c in a.off:
        label, case = c.split("=", 1)
        r = level("x0", case, t1, win)
        r["label"] = label
        off.append(r)
    labels = [r["label"] for r in levels]
    first = a.cases[0].split("=", 1)[1]
    print(f"Passage: t <= {t1*1e9:g} ns; interface series "
          + (f"averaged over {a.ifWindow:g} ns" if win else "instantaneous")
          + "; patch length "
          f"{damageIndicators.patchLength(first)*1e6:g} um; levels "
          + ", ".join(labels) + (("; off the ladder: "
                                  + ", ".join(o["label"] for o in off))
                                 if off else ""))
    print()
    head = ("| measure | " + " | ".join(labels) + " | changes | order "
            "(3 coarsest) | observed order (3 finest) | Richardson | GCI "
            f"of the finest | each level against it ({a.default} bold) | off the "
            "ladder |")
    rule = "|---|" + "---:|"*len(labels) + "---|---|---|---|---|---|---|"
    print(head)
    print(rule)
    for region in ("cytoplasm", "nucleus"):
        for q, lab, _, _ in PROBE:
            key = f"probe:{region}:{q}"
            if all(key in r for r in levels):
                print(row(f"Fig. 10 point, {region} side: {lab}", key,
                          levels, a.default, off))
    for n in INTERFACES:
        for q, lab in QUANTITIES:
            key = f"{q}:{n}"
            if all(key in r for r in levels):
                print(row(f"{n}: {lab} [Pa]", key, levels, a.default, off))
        places = sorted({k.split("_", 1)[1].split(":")[0]
                         for k in levels[0] if k.startswith("vonMisesAt_")
                         and k.endswith(":" + n)},
                        key=lambda p: ["axis", "top", "flank",
                                       "foot"].index(p)
                        if p in ("axis", "top", "flank", "foot") else 9)
        for pl in places:
            for q, lab in PLACE_QUANTITIES:
                key = f"{q}_{pl}:{n}"
                if all(key in r for r in levels):
                    print(row(f"{n}: {lab}, 1-um mean at {pl} [Pa]", key,
                              levels, a.default, off))
    print()
    for r in levels + off:
        print(f"- {r['label']}: largest von Mises 1-um mean at (r, z) [um],"
              " time [ns]: " + "; ".join(
                  "%s (%.2f, %.2f) at %.2f" % (
                      n, 1e6*r[f"at:{n}"][0], 1e6*r[f"at:{n}"][1],
                      1e9*r[f"at:{n}"][2])
                  for n in INTERFACES if f"at:{n}" in r))
        cs = ["%s %s (%.2f, %.2f) at %.2f" % (
            n, k.split("_", 1)[1].split(":")[0], 1e6*v[0], 1e6*v[1],
            1e9*r["when_" + k.split("_", 1)[1]])
            for n in INTERFACES for k, v in r.items()
            if k.startswith("centre_") and k.endswith(":" + n) and v]
        if cs:
            print(f"  fixed places' centres (r, z) [um], time of the von "
                  "Mises peak [ns]: " + "; ".join(cs))


if __name__ == "__main__":
    main()

#!/usr/bin/python3
"""The interface measures of the blast preview on a mesh ladder (issue 17
items 4 and 5; not a test).

    patchLadder.py [--pulse P] [--t1 T1] LABEL=CASE ... (LABEL: x1, x0.7,
                   x0.5: the Allrun's size factor after the 'x')

Per case, from postProcessing/solidInterfaces/*/interfacePatches.dat (the
solver's, every step): for each interface the largest over the passage
(t <= 80 ns + P, P the pulse [s], default 1.5e-8; or t <= T1 [ns]) of
the von Mises and shear means over the fixed patch length (the reported
measure) and of the element maxima of the same file (mesh-dependent).
Then the change from level to level, and from the three finest levels
the observed order and the Richardson value (bench/blast/run.py
richardson: Celik et al. 2008 for non-constant ratios; no order where
the changes alternate or do not shrink), with the deviation of x0.7 (the
default) from it. Prints a markdown table.
"""
import argparse
import importlib.machinery
import importlib.util
import os

import numpy as np

from neuronFsi import damageIndicators

HERE = os.path.dirname(os.path.abspath(__file__))
_loader = importlib.machinery.SourceFileLoader(
    "blastRun", os.path.join(HERE, "..", "run.py"))
_spec = importlib.util.spec_from_loader("blastRun", _loader)
R = importlib.util.module_from_spec(_spec)
_loader.exec_module(R)

INTERFACES = ("membrane-cytoplasm", "cytoplasm-nucleus", "membrane-fluid")
QUANTITIES = (("vonMisesPatch", "von Mises patch mean"),
              ("shearPatch", "shear patch mean"),
              ("vonMisesMax", "von Mises element max"),
              ("shearMax", "shear element max"))


def level(label, case, t1):
    ip = damageIndicators.interfacePatches(case)
    out = {"factor": float(label.lstrip("x")), "label": label}
    for n in INTERFACES:
        if n not in ip:
            continue
        d = ip[n]
        w = d["t"] <= t1
        for q, _ in QUANTITIES:
            out[f"{q}:{n}"] = d[q][w].max()
        k = np.argmax(np.where(w, d["vonMisesPatch"], -np.inf))
        out[f"at:{n}"] = (d["vonMisesPatchX"][k], d["vonMisesPatchY"][k],
                          d["t"][k])
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--pulse", type=float, default=1.5e-8)
    ap.add_argument("--t1", type=float, default=None,
                    help="end of the window [ns] (default 80 ns + pulse)")
    ap.add_argument("cases", nargs="+")
    a = ap.parse_args()
    t1 = a.t1*1e-9 if a.t1 is not None else 80e-9 + a.pulse
    levels = sorted((level(*c.split("=", 1), t1) for c in a.cases),
                    key=lambda r: -r["factor"])
    labels = [r["label"] for r in levels]
    print(f"Passage: t <= {t1*1e9:g} ns; patch length "
          f"{damageIndicators.patchLength(a.cases[0].split('=', 1)[1])*1e6:g}"
          " um")
    print()
    print("| interface | quantity [Pa] | " + " | ".join(labels)
          + " | changes | observed order | Richardson | x0.7 against it |")
    print("|---|---|" + "---:|"*len(labels) + "---|---|---|---|")
    for n in INTERFACES:
        for q, lab in QUANTITIES:
            key = f"{q}:{n}"
            if not all(key in r for r in levels):
                continue
            vals = [r[key] for r in levels]
            ch = " / ".join("%+.1f %%" % (100*(b/a_ - 1))
                            for a_, b in zip(vals, vals[1:]))
            order = ext = dev = "-"
            if len(levels) >= 3:
                res = R.richardson(levels, key)
                if res["monotone"]:
                    order = "%.2f" % res["p"]
                    ext = "%.2f" % res["ext"]
                    x07 = [r[key] for r in levels if r["label"] == "x0.7"]
                    if x07:
                        dev = "%+.1f %%" % (100*(x07[0]/res["ext"] - 1))
                else:
                    order = "none (not monotone)"
            print(f"| {n} | {lab} | " + " | ".join("%.2f" % v for v in vals)
                  + f" | {ch} | {order} | {ext} | {dev} |")
    print()
    for r in levels:
        print(f"- {r['label']}: von Mises patch centre (r, z) [um] and time "
              "[ns]: " + "; ".join(
                  "%s (%.2f, %.2f) at %.2f" % (
                      n, 1e6*r[f"at:{n}"][0], 1e6*r[f"at:{n}"][1],
                      1e9*r[f"at:{n}"][2])
                  for n in INTERFACES if f"at:{n}" in r))


if __name__ == "__main__":
    main()

#!/usr/bin/python3
"""The derived numbers of docs/results/uncertainty.md from a finished
uncertainty study (not a test; no run).

    . etc/bashrc
    bench/blast/uncertaintyNumbers.py [STUDY] [--dict DICT]

STUDY: the study's case (default tutorials/blast/pulseStudy), DICT its
dictionary (default system/pulseStudyDict.uncertainty); reads its points'
records (postProcessing/pulseStudy.uncertainty/points/*/result.json, as
pulseStudy tabulates them: applications/utilities/pulseStudy) and prints,
per pulse of the dictionary's 'uncertainty':
- per run: wall and solver CPU;
- per indicator other than von Mises: the largest relative difference of
  the variants from the base case (over the targets) and the largest
  linearised half-width relative to its value;
- von Mises per target: each variant's ratio to the base case, and for
  the nucleus that of its instantaneous shear modulus mu1 + 2 C10 (the
  base case's materials with the variant's change);
- the nucleus' von Mises half-widths at both steps against the
  proportionality I ~ mu1 + 2 C10 (its analytic derivative in ln C10 times
  sinh(h)/h) and its values at the interval's ends (not run);
- the time of each peak of the base run (the interfaces' pressure and
  von Mises over every step, the rest over the writes) and whether it is
  the last write's;
- probe 0 (paper Fig. 10): each run's pressure and von Mises peaks and
  the largest half-width of the linearised band with its time.
"""
import argparse
import math
import os
import sys

import numpy as np

from neuronFsi import script  # noqa: E402
script.guard()  # an input's error: one line, exit 1 (fix19k: every script)
from neuronFsi import damageIndicators as di, pulseStudy as ps
from neuronFsi import uncertainty as unc

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "applications",
                                "utilities", "pulseStudy"))
import pulseStudy as app  # noqa: E402  (rowOf: the study's own peaks)


def shear(mats, region):
    """mu1 + 2 C10 [Pa] of a region."""
    return mats[region]["mu1"] + 2*mats[region]["C10"]


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("study", nargs="?", default=os.path.join(
        HERE, "..", "..", "tutorials", "blast", "pulseStudy"))
    ap.add_argument("--dict", default="system/pulseStudyDict.uncertainty")
    a = ap.parse_args()
    case = os.path.abspath(a.study)
    s = ps.read(case, a.dict)
    u = s["uncertainty"]
    out = os.path.join(case, ps.output(a.dict), "points")
    grid = {(p["overpressure"], p["duration"]): p for p in ps.points(s)}
    variants = list(u["variants"])
    for A, T in u["pulses"]:
        g = grid[(A, T)]["label"]
        names = ["base"] + [n for n, _ in unc.runs(u)]
        rec = {n: ps.readRecord(os.path.join(
            out, g if n == "base" else "%s_%s" % (g, n), "result.json"))
            for n in names}
        rows = {n: app.rowOf(s, r)[0] for n, r in rec.items()}
        print("== %g Pa, %g s (%s): %d runs" % (A, T, g, len(names)))
        wall = [r["wall"] for r in rec.values()]
        cpu = [r["cpu"] for r in rec.values()]
        print("wall per run %.0f-%.0f s (sum %.0f s); solver CPU per run "
              "%.1f-%.1f s (sum %.0f s)" % (min(wall), max(wall), sum(wall),
                                           min(cpu), max(cpu), sum(cpu)))
        targets = list(rec["base"]["series"]["targets"])

        def col(t, ind):
            return "%s:%s [%s]" % (t, ind, di.UNITS[ind])

        def lin(c):
            return unc.propagate(u, lambda n: rows[n][c])
        print("-- largest relative difference of a variant from the base "
              "case; largest half-width (step %g) / value" % u["step"])
        for ind in di.INDICATORS:
            worst, where, hw, hwWhere = 0.0, "", 0.0, ""
            for t in targets:
                c = col(t, ind)
                b = rows["base"][c]
                if not np.isfinite(b):
                    continue
                for v in variants:
                    d = abs(rows[v][c]/b - 1)
                    if d >= worst:
                        worst, where = d, "%s %s" % (t, v)
                L = lin(c)
                h = float(L["halfWidth"])/abs(float(L["about"]))
                if h >= hw:
                    hw, hwWhere = h, t
            print("%-16s variants %.2g (%s); half-width %.2g (%s)"
                  % (ind, worst, where, hw, hwWhere))
        print("-- von Mises: ratio of each variant to the base case")
        mats = {"base": u["base"]}
        for v, change in u["variants"].items():
            mats[v] = unc.materialsOf(u["base"], change)
        for t in targets:
            c = col(t, "vonMises")
            print("%-20s base %.6g Pa; %s" % (t, rows["base"][c], ", ".join(
                "%s %.6f" % (v, rows[v][c]/rows["base"][c])
                for v in variants)))
        print("nucleus mu1 + 2 C10 ratio: %s (base %.6g Pa)" % (", ".join(
            "%s %.6f" % (v, shear(mats[v], "nucleus")/shear(mats["base"],
                                                            "nucleus"))
            for v in variants), shear(mats["base"], "nucleus")))
        print("cytoplasm mu1 + 2 C10 ratio: %s (base %.6g Pa)" % (", ".join(
            "%s %.6f" % (v, shear(mats[v], "cytoplasm")/shear(
                mats["base"], "cytoplasm")) for v in variants),
            shear(mats["base"], "cytoplasm")))
        for t in targets:
            c = col(t, "vonMises")
            L = lin(c)
            print("%-20s about %s %.6g Pa +- %.6g (step %g) / %.6g (%g): "
                  "ratio %.5f, %.3g %% of the value" % (
                      t, u["about"], float(L["about"]),
                      float(L["halfWidth"]), u["step"],
                      float(L["halfWidthCheck"]), u["checkStep"],
                      float(L["halfWidth"])/float(L["halfWidthCheck"])
                      if float(L["halfWidthCheck"]) > 0 else math.nan,
                      100*float(L["halfWidth"])/float(L["about"])))
        # the proportionality's prediction for the nucleus
        m = mats[u["about"]]["nucleus"]
        p = next(q for q in u["parameters"] if q["name"] == "nucleus.C10")
        c = col("nucleus", "vonMises")
        I0 = rows[u["about"]][c]
        dIdx = I0*2*m["C10"]/(m["mu1"] + 2*m["C10"])
        L = lin(c)
        k = [i for i, q in enumerate(u["parameters"]) if q is p][0]
        print("nucleus von Mises: dI/d ln C10 = %.6f Pa (I0 2 C10/(mu1 + 2 "
              "C10)); x sinh(h)/h: %.6f (h %g), %.6f (h %g); the runs' "
              "central differences %.6f, %.6f Pa" % (
                  dIdx, dIdx*math.sinh(u["step"])/u["step"], u["step"],
                  dIdx*math.sinh(u["checkStep"])/u["checkStep"],
                  u["checkStep"], float(L["derivatives"][k]),
                  float(L["derivativesCheck"][k])))
        lo, hi = [p["value"]*math.exp(sg*p["halfWidth"]) for sg in (-1, 1)]
        Ilo, Ihi = [I0*(m["mu1"] + 2*x)/(m["mu1"] + 2*m["C10"])
                    for x in (lo, hi)]
        print("over [%.4g, %.4g] Pa (proportionality, not run): %.6g to "
              "%.6g Pa (%+.4f / %+.4f Pa about %.6g), half the range %.4f "
              "against the linearised %.4f Pa (%+.1f %%)" % (
                  lo, hi, Ilo, Ihi, Ilo - I0, Ihi - I0, I0, (Ihi - Ilo)/2,
                  float(L["halfWidth"]),
                  100*(float(L["halfWidth"])/((Ihi - Ilo)/2) - 1)))
        print("-- the base run's peak times [ns] (* the last write's)")
        ser = rec["base"]["series"]
        tw = np.array(ser["t"])
        for t in targets:
            step = ser["interfaces"].get(t)
            parts = []
            for ind in di.INDICATORS:
                y = np.array(ser["targets"][t][ind], float)
                tt = tw
                if step is not None and ind in ("pressure", "vonMises"):
                    tt = np.array(step[0])
                    y = np.array(step[1 if ind == "pressure" else 2])
                if not np.any(np.isfinite(y)):
                    continue
                i = int(np.nanargmax(y))
                parts.append("%s %.2f%s" % (ind, tt[i]*1e9,
                                            "*" if i == len(y) - 1 else ""))
            print("%-20s %s" % (t, ", ".join(parts)))
        print("-- probe 0 (paper Fig. 10)")
        pr = {n: r["series"]["probe"] for n, r in rec.items()}
        for n in ["base"] + variants:
            P = np.array(pr[n]["pressure"])
            V = np.array(pr[n]["vonMises"])
            tp = np.array(pr[n]["t"])
            print("%-14s pressure peak %.3f MPa at %.2f ns; von Mises peak "
                  "%.4f Pa at %.2f ns" % (n, P.max()*1e-6,
                                          tp[P.argmax()]*1e9, V.max(),
                                          tp[V.argmax()]*1e9))
        tref = np.array(pr[u["about"]]["t"])
        for key, k_, unit in (("pressure", 1e-6, "MPa"),
                              ("vonMises", 1, "Pa"), ("strainZ", 1, "-"),
                              ("strainRateZ", 1, "1/s")):
            L = unc.propagate(u, lambda n: np.interp(
                tref, pr[n]["t"], pr[n][key]))
            H = L["halfWidth"]*k_
            i = int(np.nanargmax(H))
            top = np.nanmax(np.abs(L["about"]*k_))
            print("band %-12s largest half-width %.2g %s (%.2g %% of the "
                  "largest |value| %.4g) at %.2f ns" % (
                      key, H[i], unit, 100*H[i]/top, top, tref[i]*1e9))


if __name__ == "__main__":
    main()

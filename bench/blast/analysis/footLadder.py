#!/usr/bin/python3
"""The membrane-cytoplasm interface maximum at the cell's foot, per case of
a mesh ladder (issue 17 item 5; not a test).

    footLadder.py [--t0 60] [--t1 95] [--near 1.0] [--away 1.0]
                  LABEL=CASE [LABEL=CASE ...]

The foot: where the membrane, bonded to the rigid substrate (its nodes on
z = 0 fixed), meets the water that slips along the substrate; the contact
point P is the membrane's node on z = 0 of largest r. Over the writes of
CASE/solid/solid.h5 with T0 <= t <= T1 [ns], for the membrane-cytoplasm
band (the elements of either region with a node on the other, as
postProcessing/solidInterfaces and interfaceTop.py), the largest over the
writes of:

  band max      the largest element von Mises of the band (the reported
                interface maximum, sampled at the writes);
  foot el.      the von Mises of the band's membrane element nearest P;
  away max      the largest over band elements whose centroid lies more
                than --away [um] from P (the maximum away from the
                contact point);
  foot mean     the area-weighted mean von Mises of the band's membrane
                elements whose centroid lies within --near [um] of P (an
                average over a fixed physical length of the membrane);
  patch max     the largest, over the band elements, of the mean von
                Mises of the band elements of the same region within
                --near [um] of it (interfaceTop.patchMaximum: the
                interface maximum of a mean over a fixed length instead
                of one element);

each with the write time [ns] it was reached at, and the membrane's
tangential element size at the foot [um]; and from
postProcessing/solidInterfaces (every step, not only the writes) the
membrane-cytoplasm maximum in each --windows interval [ns] (default
60-74, before the substrate's echo reaches the foot, and 74-95, after
it) with its time. Prints a markdown table and, for
three or more cases in the order given (coarse to fine), the changes from
level to level.
"""
import argparse

import importlib.machinery
import importlib.util
import os

import numpy as np

from neuronFsi import script  # noqa: E402
# an input's error is one line, not a traceback (adv52 p18)
script.guard()
from neuronFsi import damageIndicators
from neuronFsi.solidResults import SolidResults

_loader = importlib.machinery.SourceFileLoader(
    "interfaceTop", os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                 "interfaceTop.py"))
_spec = importlib.util.spec_from_loader("interfaceTop", _loader)
T = importlib.util.module_from_spec(_spec)
_loader.exec_module(T)


def footMeasures(case, t0, t1, near, away):
    """{measure: (value [Pa], time [ns])} and the foot element's size"""
    with SolidResults(case + "/solid/solid.h5") as f:
        X = f.mesh("coordinates")[:, :2]
        conn = f.mesh("connectivity")
        reg = f.mesh("region").ravel()
        C = X[conn].mean(axis=1)
        area = T.quadAreas(X, conn)
        mem = np.unique(conn[reg == T.NAMES.index("membrane")].ravel())
        base = mem[np.abs(X[mem, 1]) < 1e-12]
        if len(base) == 0:
            raise SystemExit(f"{case}: no membrane node on z = 0")
        P = X[base[np.argmax(X[base, 0])]]
        els = T.band(conn, reg, "membrane", "cytoplasm")
        dist = np.linalg.norm(C[els] - P, axis=1)
        memBand = els[reg[els] == T.NAMES.index("membrane")]
        memDist = np.linalg.norm(C[memBand] - P, axis=1)
        foot = memBand[np.argmin(memDist)]
        nearEls = memBand[memDist <= near*1e-6]
        awayEls = els[dist > away*1e-6]
        # the foot element's tangential size: its extent in z
        size = np.ptp(X[conn[foot], 1])
        best = {k: (-1.0, 0.0) for k in
                ("band max", "foot el.", "away max", "foot mean",
                 "patch max")}
        for s in f.steps():
            t = f.time(s)*1e9
            if t < t0 or t > t1:
                continue
            vm = f.field(s, "vonMises").ravel()
            vals = {
                "band max": vm[els].max(),
                "foot el.": vm[foot],
                "away max": vm[awayEls].max(),
                "foot mean": np.sum(vm[nearEls]*area[nearEls])
                / np.sum(area[nearEls]),
                "patch max": T.patchMaximum(C, reg, els, vm, near*1e-6)[0],
            }
            for k, v in vals.items():
                if v > best[k][0]:
                    best[k] = (v, t)
    return best, size*1e6, len(nearEls), P*1e6


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--t0", type=float, default=60.0)
    ap.add_argument("--t1", type=float, default=95.0)
    ap.add_argument("--near", type=float, default=1.0)
    ap.add_argument("--away", type=float, default=1.0)
    ap.add_argument("--windows", default="60-74 74-95")
    ap.add_argument("cases", nargs="+")
    a = ap.parse_args()
    keys = ("band max", "foot el.", "away max", "foot mean", "patch max")
    rows = []
    print(f"writes {a.t0:g}-{a.t1:g} ns; foot mean over the band's "
          f"membrane elements within {a.near:g} um of the contact point; "
          f"away max beyond {a.away:g} um\n")
    print("| case | foot element size [um] | contact point (r, z) [um] | "
          + " | ".join(f"{k} [Pa] (t [ns])" for k in keys) + " |")
    print("|---|---|---|" + "---|"*len(keys))
    for c in a.cases:
        if "=" not in c:
            ap.error("%s: give LABEL=CASE" % c)
        label, case = c.split("=", 1)
        best, size, n, P = footMeasures(case, a.t0, a.t1, a.near, a.away)
        rows.append((label, best))
        print(f"| {label} | {size:.3f} | ({P[0]:.2f}, {P[1]:.2f}) | "
              + " | ".join(f"{best[k][0]:.2f} ({best[k][1]:.2f})"
                           for k in keys)
              + f" |  <!-- foot mean over {n} elements -->")
    windows = [tuple(float(x) for x in w.split("-"))
               for w in a.windows.split()]
    print("\nmembrane-cytoplasm maximum of postProcessing/solidInterfaces "
          "(every step) [Pa] (t [ns]):\n")
    print("| case | " + " | ".join(f"{w0:g}-{w1:g} ns" for w0, w1 in windows)
          + " |")
    print("|---|" + "---|"*len(windows))
    for c in a.cases:
        if "=" not in c:
            ap.error("%s: give LABEL=CASE" % c)
        label, case = c.split("=", 1)
        t, _, vm = damageIndicators.interfaceMaxima(case)["membrane-cytoplasm"]
        t = t*1e9
        cells = []
        for w0, w1 in windows:
            s = (t >= w0) & (t <= w1)
            k = np.argmax(np.where(s, vm, -np.inf))
            cells.append(f"{vm[k]:.2f} ({t[k]:.2f})")
        print(f"| {label} | " + " | ".join(cells) + " |")
    if len(rows) >= 2:
        print("\nchange from the previous case [%]:\n")
        for (l0, b0), (l1, b1) in zip(rows, rows[1:]):
            print(f"- {l0} -> {l1}: " + ", ".join(
                f"{k} {100*(b1[k][0]/b0[k][0] - 1):+.1f} %" for k in keys))


if __name__ == "__main__":
    main()

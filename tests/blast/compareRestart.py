#!/usr/bin/python3
"""Compare the postProcessing logs of an interrupted and restarted
cellBlastFoam run (KILLED) with those of an uninterrupted one (REF).

    compareRestart.py REF KILLED [--tol 1e-10] [--bitwise] [--pulse P]
                      [--h5] [--fluid]

Every start of KILLED wrote its logs to postProcessing/<log>/<start time>/;
they are put together in time: from each start, its rows up to the next
start. Each row is compared with the reference row of the same step:
every column within TOL of the column's largest magnitude (a von Mises
column of the solid probes: beyond its round-off floor, 16 eps of the
probes' largest pressure, from which it is computed), time, dt,
iterations and the converged flag of coupling.dat exactly; with --bitwise
every compared value exactly. Every log (coupling.dat, solidProbes,
interfaceMaxima) is flushed at every write time, before the time is
committed, so each must be complete: every reference row present (rows a
killed start wrote after its last write time are recomputed by the next
start). --pulse P: the first probe's
pressure must exceed P [Pa] after the last start (the pulse is in the cell
over a compared window). --h5: solid/solid.h5 must hold the same steps
(index, and time within TOL; --bitwise: equal) as the reference's,
every dataset within TOL of its largest magnitude over the steps
(--bitwise: equal). --fluid: the water probes' pressure
(postProcessing/fluidProbes/<start>/p, over all starts) too: the same
number of rows, times within TOL of the time (the probes print the time
at the write precision, where another decomposition's Courant step
differs in the last bits; --bitwise: equal), every probe within TOL of its
column's largest magnitude (--bitwise: equal).
"""
import argparse
import os
import sys

import numpy as np

from neuronFsi import script  # noqa: E402
script.guard()  # an input's error: one line, exit 1 (fix19k: every script)
from neuronFsi import postProcessing

# log, columns compared (None: all; a function: of the column names),
# exact columns, complete
LOGS = (
    # not compared: the final residual (a convergence measure below the
    # tolerance), the swirl component of the force (zero but for round-off,
    # 1e-20 N), gclError (round-off, 1e-14): columns 3, 7, 9; compared
    # too: the interface works of fluid and solid (10, 11)
    ("fsi/coupling.dat", (0, 1, 2, 4, 5, 6, 8, 10, 11), (0, 1, 2, 4), True),
    ("solidProbes/solidProbes.dat", None, (0,), True),
    ("solidInterfaces/interfaceMaxima.dat", None, (0,), True),
    # not compared: the von Mises patches' centres (where two patches'
    # means agree to round-off the centre may move by a patch; the means
    # are compared)
    ("solidInterfaces/interfacePatches.dat",
     lambda names: [j for j, n in enumerate(names)
                    if not n.startswith(("vonMisesPatchX", "vonMisesPatchY",
                                         "vonMisesPatchZ"))], (0,), True),
    # the means at fixed places (solidProperties interfacePlaces)
    ("solidInterfaces/interfacePlaces.dat", None, (0,), True),
)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("ref")
    ap.add_argument("killed")
    ap.add_argument("--tol", type=float, default=1e-10)
    ap.add_argument("--bitwise", action="store_true")
    ap.add_argument("--pulse", type=float, default=None)
    ap.add_argument("--h5", action="store_true")
    ap.add_argument("--fluid", action="store_true")
    a = ap.parse_args()
    ref, killed, tol, bitwise = a.ref, a.killed, a.tol, a.bitwise
    ok = True
    if a.fluid:
        ok &= compareFluidProbes(ref, killed, tol, bitwise)
    for log, cols, exact, complete in LOGS:
        try:
            segs = postProcessing.segments(ref, log)
        except postProcessing.ColumnFileError:
            continue
        r = postProcessing.readTable(segs[0][1]).data()
        ncols = r.shape[1]
        # von Mises (a few Pa) comes from stresses of the pressure's size
        # (1e8 Pa): its round-off floor is eps x that, about 4e-9 of its
        # own range. Its column allows that floor (16 eps of the probes'
        # largest pressure [Pa]) on top of TOL.
        names = postProcessing.names(ref, log)
        pScale = max([np.abs(r[:, j]).max() for j, n in enumerate(names)
                      if n[:1] == "p" and n[1:].isdigit()], default=0)
        vonMisesFloor = np.array([16*np.finfo(float).eps*pScale
                                  if n.startswith("vonMises") else 0
                                  for n in names])
        ks = postProcessing.segments(killed, log)
        compared = missing = 0
        worst = np.zeros(ncols)
        same = True
        # Each start's rows up to the first row of the next start (the
        # directory names are rounded to timePrecision: rows, not names,
        # delimit the starts)
        segs = [(t0, postProcessing.readTable(path).data())
                for t0, path in ks]
        segs = [(t0, k) for t0, k in segs if len(k)]
        for i, (t0, k) in enumerate(segs):
            t1 = segs[i + 1][1][0, 0] if i + 1 < len(segs) else np.inf
            k = k[k[:, 0] < t1]
            rr = r[(r[:, 0] >= k[0, 0]) & (r[:, 0] < t1)]
            if len(k) > len(rr) or not np.array_equal(rr[:len(k), 0],
                                                      k[:, 0]):
                print("%s: the steps of the start at %g s are not the "
                      "reference's" % (log, t0))
                ok = False
                continue
            missing += len(rr) - len(k)
            if complete and len(rr) != len(k):
                print("%s: the start at %g s lacks %d of the reference's "
                      "rows before %g s" % (log, t0, len(rr) - len(k), t1))
                ok = False
            rr = rr[:len(k)]
            compared += len(k)
            c = (list(range(ncols)) if cols is None
                 else cols(names) if callable(cols) else list(cols))
            scale = np.maximum(np.abs(r[:, c]).max(axis=0), 1e-300)
            floor = np.array([vonMisesFloor[j]/scale[k_]
                              for k_, j in enumerate(c)])
            if (a.pulse is not None and log.startswith("solidProbes")
                    and i == len(segs) - 1):
                peak = k[:, 1].max() if len(k) else 0
                print("%s: probe peak pressure after the last start (%g s) "
                      "%.4g MPa" % (log, t0, peak/1e6))
                ok &= peak > a.pulse
            if len(k):
                d = np.maximum(np.abs(rr[:, c] - k[:, c])/scale - floor, 0)
                worst[c] = np.maximum(worst[c], d.max(axis=0))
                same &= np.array_equal(rr[:, c], k[:, c])
                for j in exact:
                    if not np.array_equal(rr[:, j], k[:, j]):
                        print("%s: column %d differs after the start at %g s"
                              % (log, j, t0))
                        ok = False
        print("%s: %d starts, %d rows compared, %d missing, largest "
              "difference %.3e of the "
              "column range (per column: %s), bitwise %s"
              % (log, len(ks), compared, missing, worst.max(),
                 " ".join("%.1e" % x for x in worst), same))
        ok &= compared > 0 and worst.max() <= tol
        if bitwise:
            ok &= same
    if a.h5:
        ok &= compareH5(os.path.join(ref, "solid", "solid.h5"),
                        os.path.join(killed, "solid", "solid.h5"), tol,
                        bitwise)
    sys.exit(0 if ok else 1)


def compareFluidProbes(ref, killed, tol, bitwise):
    """The water probes' pressure of the two runs: same rows, times within
    tol of the time, values within tol of each column's largest magnitude
    (bitwise: equal)."""
    log = "fluidProbes/p"
    try:
        r = postProcessing.series(ref, log)
        k = postProcessing.series(killed, log)
    except postProcessing.ColumnFileError as err:
        print("%s: %s" % (log, err))
        return False
    if r.shape != k.shape or not len(r):
        print("%s: %d x %d values in the reference, %d x %d here"
              % (log, *r.shape, *k.shape))
        return False
    dt = np.abs(r[:, 0] - k[:, 0]).max()/np.abs(r[:, 0]).max()
    scale = np.maximum(np.abs(r[:, 1:]).max(axis=0), 1e-300)
    worst = (np.abs(r[:, 1:] - k[:, 1:])/scale).max(axis=0)
    same = np.array_equal(r, k)
    print("%s: %d rows, times within %.3e of the last, largest difference "
          "%.3e of the column range (per probe: %s), bitwise %s"
          % (log, len(r), dt, worst.max(),
             " ".join("%.1e" % x for x in worst), same))
    return same if bitwise else (dt <= tol and worst.max() <= tol)


def compareH5(ref, killed, tol, bitwise):
    """Same steps and times, every dataset of every step within tol
    (bitwise: equal)."""
    import h5py

    def steps(f):
        return sorted((int(k), f["steps"][k].attrs["time"])
                      for k in f["steps"])

    def datasets(g):
        names = []
        g.visititems(lambda name, obj: names.append(name)
                     if isinstance(obj, h5py.Dataset) else None)
        return names

    with h5py.File(ref, "r") as a, h5py.File(killed, "r") as b:
        sa, sb = steps(a), steps(b)
        # step times exactly (bitwise) or within tol of the time (another
        # decomposition: the Courant step differs in the last bits)
        if [k for k, _ in sa] != [k for k, _ in sb] or any(
                (ta != tb) if bitwise else abs(ta - tb) > tol*abs(ta)
                for (_, ta), (_, tb) in zip(sa, sb)):
            print("solid.h5: the steps (index, time) differ: %d in the "
                  "reference, %d here" % (len(sa), len(sb)))
            return False
        worst, same, n, where = 0.0, True, 0, ""
        # scale of a dataset: its largest magnitude over all steps (as the
        # column range of the logs; a field at rest is round-off)
        scale = {}
        for k, _ in sa:
            ga = a["steps"][str(k)]
            for name in datasets(ga):
                x = ga[name][()]
                if x.size:
                    scale[name] = max(scale.get(name, 1e-300),
                                      np.abs(x).max())
        for k, _ in sa:
            ga, gb = a["steps"][str(k)], b["steps"][str(k)]
            for name in datasets(ga):
                x, y = ga[name][()], gb[name][()]
                n += 1
                same &= np.array_equal(x, y)
                if x.size:
                    d = np.abs(x - y).max()/scale[name]
                    if d > worst:
                        worst, where = d, "step %d %s" % (k, name)
        print("solid.h5: %d steps, %d datasets, largest difference %.3e of "
              "the dataset's largest magnitude%s, bitwise %s"
              % (len(sa), n, worst, " (%s)" % where if where else "", same))
        return worst <= tol and (same or not bitwise)


if __name__ == "__main__":
    main()

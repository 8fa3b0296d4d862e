#!/usr/bin/python3
"""Point probes of the pressure at a region interface that do not
extrapolate a front (issue 17; docs/results/blast3D.md, "The von Mises at
rest in 3D", last part); not a test. For a run of bench/blast/
probeOvershoot3D.sh (solid/solid.h5 every 0.2 ns through the incident
passage; DIR/ref1d.npz the 1D answer written by probeOvershoot.py):

    bench/blast/interfaceProbeVariants.py CASE --reference REF.npz

At the Fig. 10 point (the probes 0 and 1 of postProcessing/solidProbes:
the same point, cytoplasm and nucleus side) prints planeWave's measures
(arrival, 1-ns peak, incident 1-ns peak, plateau) against the 1D answer
at the point for these readings of the element pressures, each applied
to the exact field (every element holding the 1D answer averaged over
it) and to the scene's element pressures:

 - one-sided fit: solid::PointProbe (the containing element and its
   region's elements sharing a node with it, a linear least-squares fit
   at the centroids, evaluated at the point; weights -0.30 to +0.48);
 - host: the containing element's average (no fit);
 - two-sided fit: the same linear fit over the union of both sides'
   patches (the pressure is continuous across the interface in the exact
   answer: both sides have water's volumetric law and the deviatoric
   stresses are 1e-7 of it), so that the point lies among the centroids;
 - two hosts: linear between the two containing elements' centroids
   along the segment joining them, the point projected on it and clipped
   to it (weights in [0, 1]: never an extrapolation).
"""

import argparse
import os
import sys

import h5py
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from probeOvershoot import (Cell, Reference, fmt, measure,  # noqa
                            passagePressures, probeHistory)


def fit(cell, Xp, patch):
    """Weights of the linear least-squares fit over the centroids of
    patch, evaluated at Xp (solid::PointProbe's construction)."""
    return cell.fitWeights(Xp, patch)


def main():
    a = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    a.add_argument("case")
    a.add_argument("--reference", required=True)
    o = a.parse_args()
    case = os.path.abspath(o.case)
    probes, _ = probeHistory(case)
    ref = Reference(o.reference)
    with h5py.File(os.path.join(case, "solid", "solid.h5"), "r") as h5:
        cell = Cell(h5)
        ts, P = passagePressures(h5)
    sides = {}
    for num, name, x, y, z, region, host, nPatch in probes:
        if region not in sides:
            sides[region] = (np.array([float(x), float(y), float(z)]),
                             int(host))
    if len(sides) != 2:
        sys.exit("interfaceProbeVariants.py: probes on two sides wanted")
    (ra, (Xp, ha)), (rb, (_, hb)) = sides.items()
    pa, wa = cell.recovery(Xp, ha)
    pb, wb = cell.recovery(Xp, hb)
    union = pa + pb
    wu = fit(cell, Xp, union)
    ca, cb = cell.centroid(ha), cell.centroid(hb)
    s = float(np.clip((Xp - ca) @ (cb - ca)/((cb - ca) @ (cb - ca)), 0, 1))
    print("point (%.3f, %.3f, %.3f) um; hosts %d (%s, centroid %.2f um "
          "away) and %d (%s, %.2f um); two hosts: weights %.3f / %.3f "
          "(the point %.2f um off their segment); two-sided fit over %d "
          "elements: weights %+.3f to %+.3f"
          % (*(Xp*1e6), ha, ra, np.linalg.norm(ca - Xp)*1e6, hb, rb,
             np.linalg.norm(cb - Xp)*1e6, 1 - s, s,
             np.linalg.norm(ca + s*(cb - ca) - Xp)*1e6, len(union),
             wu.min(), wu.max()))
    avg = {e: ref.elementAverage(cell, e) for e in set(union)}
    variants = [
        ("one-sided fit, %s" % ra, list(zip(pa, wa))),
        ("one-sided fit, %s" % rb, list(zip(pb, wb))),
        ("host, %s" % ra, [(ha, 1.0)]),
        ("host, %s" % rb, [(hb, 1.0)]),
        ("two-sided fit", list(zip(union, wu))),
        ("two hosts", [(ha, 1 - s), (hb, s)]),
    ]
    pX = ref.at(Xp[2])
    for label, ew in variants:
        exact = sum(w*avg[e] for e, w in ew)
        scene = sum(w*P[:, e] for e, w in ew)
        print("%-26s exact field: %s" % (label, fmt(measure(ref.t, exact,
                                                            ref.t, pX,
                                                            Xp[2]))))
        print("%-26s scene:       %s" % ("", fmt(measure(ts, scene, ref.t,
                                                         pX, Xp[2]))))


if __name__ == "__main__":
    main()

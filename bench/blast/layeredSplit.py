#!/usr/bin/env python3
"""What the layered reference changes at the probes, split in two (issue
17 item 1; not a test): the cell's layers (membrane, cytoplasm, nucleus
against water only) and the solid probe's sampling (its material point,
as the scene's solid probes follow theirs, against the fixed height, as
the water-only reference samples it). Four columns of
neuronFsi.layeredColumn (water-only or layered x fixed height or
material point) at cells of DZ; the measures of neuronFsi.planeWave at
the solid probe's height (windows of the water-only fixed-height column)
and the 1-ns peak of the uniaxial strain ln(rho0/rho); at the water probe
(10 um) the 1-ns peak and the plateau.

Usage: layeredSplit.py CASE [DZ]   (DZ default 20e-9 m; CASE a preview
run of tests/blast/runPreview.sh: its solid probe and pulse)
"""
import sys

from neuronFsi import script  # noqa: E402
script.guard()  # an input's error: one line, exit 1 (adv53 u12)
script.arguments(1, "CASE [dz]")
from neuronFsi import layeredColumn as lc
from neuronFsi import planeWave as pw


def main():
    case = sys.argv[1]
    dz = float(sys.argv[2]) if len(sys.argv) > 2 else 20e-9
    amp, T = pw.pulseShape(pw.appliedPressure(case))
    probes = pw.caseProbes(case)
    z = [q[1] for q in probes if q[0].startswith("solid")][0]
    zw = 10e-6
    end = max(q[2][-1] for q in probes)
    Z = pw.caseColumnHeight(case)
    res = {}
    for water in (True, False):
        for mat in (False, True):
            res[(water, mat)] = lc.solve(case, [z, zw], Z, end, dz=dz,
                                         water=water,
                                         material=[z] if mat else [])
    ref = res[(True, False)]
    print("solid probe at z = %.4g um, water probe at %.4g um, cells %g nm"
          % (z*1e6, zw*1e6, dz*1e9))
    print("| column | solid probe sampled at | 1-ns peak [MPa] | incident "
          "peak [MPa] | plateau [MPa] | impulse [Pa s] | strain 1-ns peak "
          "| water %g um: 1-ns peak [MPa]; plateau [MPa] |" % (zw*1e6))
    print("|---|---|---:|---:|---:|---:|---:|---|")
    for (water, mat), w in res.items():
        s, _ = pw.measures(w.t, w.at(z), ref.t, ref.at(z), amp, T, z)
        ez, _ = pw.uniaxialResponse(w.t, w.densityAt(z), 1000.0, 0.0)
        _, me = pw.runningMean(w.t, ez, 1e-9)
        sw, _ = pw.measures(w.t, w.at(zw), ref.t, ref.at(zw), amp, T, zw)

        def f(v, scale=1e-6, fmt="%.3f"):
            return "-" if v is None else fmt % (v*scale)

        print("| %s | %s | %s | %s | %s | %s | %.6f | %s; %s |" % (
            "water only" if water else "layered",
            "material point" if mat else "fixed height",
            f(s["peak1ns"]), f(s["peakIncident"]), f(s["plateau"]),
            f(s["impulse"], 1, "%.5f"), me.min(), f(sw["peak1ns"]),
            f(sw["plateau"])))


if __name__ == "__main__":
    main()

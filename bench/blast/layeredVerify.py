#!/usr/bin/env python3
"""Verification of the layered 1D column (neuronFsi.layeredColumn; issue
17 item 1), not a test (the unit tests are python.LayeredColumn):

1. wall: a 50 MPa step on a 5 um column onto the rigid wall, the wall's
   pressure after the reflection (mean from 4.0 to 4.5 ns) against the
   exact collision (layeredColumn.wallCollision: 104.43 MPa for water's
   law, 100 MPa for the membrane's), cells of the -dz sizes;
2. rhoRiemannFoam: the water-only column of CASE (no layers) against
   planeWave's reference (rhoRiemannFoam, -rdz cells, or the file of
   -reference), the measures of neuronFsi.planeWave at the case's probe
   heights (the solid's at fixed heights here, as the water-only
   reference samples them);
3. order: the layered column of CASE (its layers on the axis) at the -dz
   sizes, its measures at the probes (the solid's at material points) and
   the observed order of their changes;
4. top (not in the default parts): the water-only column with the pulse
   applied on the moving top node itself, against the fixed plane Z (the
   delay of layeredColumn), cells of the last -dz.

Usage: layeredVerify.py CASE [-dz 40e-9,20e-9,10e-9] [-rdz 25e-9]
           [-reference FILE] [-parts wall,rhoRiemann,order,top]
CASE: a blast case that has run (its probes and solid mesh), e.g. the
preview of tests/blast/runPreview.sh DIR -pulse 5e-9 -noPlots -noVTK.
"""
import argparse
import math
import os
import sys
import time


from neuronFsi import script  # noqa: E402
# an input's error is one line, not a traceback (adv52 p18)
script.guard()
from neuronFsi import layeredColumn as lc
from neuronFsi import planeWave as pw

KEYS = ("arrival", "peak1ns", "peakIncident", "plateau", "impulse")


def wall(sizes):
    print("1. wall: 50 MPa step onto the rigid wall, 5 um column; the wall "
          "pressure from 4.0 to 4.5 ns against the exact collision")
    w = lc.MieGruneisen(1000.0, 1450.0, 1.99, 0.1, 4184.0, 293.15)
    m = lc.Quadratic(1000.0, 9.5125e-10)
    print("| law | exact [MPa] | " + " | ".join("%g nm" % (d*1e9)
                                                for d in sizes) + " |")
    print("|---|---:|" + "---:|"*len(sizes))
    for law, name in ((w, "water (Mie-Grueneisen)"),
                      (m, "membrane (quadratic)")):
        exact = lc.wallCollision(law, 5e7)[0]
        cells = []
        for dz in sizes:
            col = lc.Column([(0.0, 5e-6, law)], w, 5e-6, dz)
            t, P, _, _, _, _ = col.run([(0, 0), (1e-10, 5e7), (1, 5e7)],
                                       7.5e-9, eulerian=[0.0])
            # the reflection reaches the wall at 0.05 + 5/1516 = 3.35 ns
            # (water), 3.5 ns (membrane): the window after its arrival
            late = P[(t > 4.0e-9) & (t < 4.5e-9), 0].mean()
            cells.append("%.4f (%+.3f %%)" % (late/1e6,
                                               100*(late/exact - 1)))
        print("| %s | %.4f | %s |" % (name, exact/1e6, " | ".join(cells)))


def row(wave, ref, z, amp, T):
    """the measures of wave at z with ref's windows, and ref's"""
    s, r = pw.measures(wave.t, wave.at(z), ref.t, ref.at(z), amp, T, z)
    return s, r, pw.errors(s, r)


def fmt(k, v):
    if v is None:
        return "-"
    return "%+.3f ns" % (v*1e9) if k == "arrival" else "%+.3f %%" % (100*v)


def rhoRiemann(case, sizes, rdz, reference, heights, amp, T, Z, end):
    print("\n2. the water-only column of %s against rhoRiemannFoam (%s)"
          % (case, reference or "%g nm cells" % (rdz*1e9)))
    if reference:
        ref = pw.readReference(reference)
        end = min(end, ref.t[-1])
    else:
        t0 = time.process_time()
        ref = pw.column(case, heights, Z, end, dz=rdz)
        print("rhoRiemannFoam column: %.1f s CPU (its child)"
              % (time.process_time() - t0))
    print("| cells | height [um] | " + " | ".join(KEYS) + " | CPU [s] |")
    print("|---|---:|" + "---:|"*(len(KEYS) + 1))
    for dz in sizes:
        t0 = time.process_time()
        wave = lc.solve(case, heights, Z, end, dz=dz, water=True)
        cpu = time.process_time() - t0
        for z in heights:
            _, _, e = row(wave, ref, z, amp, T)
            print("| %g nm | %.4g | %s | %.1f |" % (
                dz*1e9, z*1e6, " | ".join(fmt(k, e[k]) for k in KEYS), cpu))


def order(case, sizes, heights, material, amp, T, Z, end):
    print("\n3. the layered column of %s (axis): measures at the probes "
          "and their changes with the cell size" % case)
    waves = []
    for dz in sizes:
        t0 = time.process_time()
        waves.append(lc.solve(case, heights, Z, end, dz=dz,
                              material=material))
        print("%g nm: %d cells, %d samples, %.1f s CPU; layers %s" % (
            dz*1e9, waves[-1].cells, len(waves[-1].t),
            time.process_time() - t0, ", ".join(
                "%s %.4f-%.4f um" % (n, a*1e6, b*1e6)
                for a, b, n in waves[-1].layers)))
    # the windows of the finest
    fine = waves[-1]
    print("| height [um] | measure | " + " | ".join(
        "%g nm" % (d*1e9) for d in sizes) + " | observed order |")
    print("|---:|---|" + "---:|"*(len(sizes) + 1))
    for z in heights:
        vals = {k: [] for k in KEYS}
        for w in waves:
            s, _, _ = row(w, fine, z, amp, T)
            for k in KEYS:
                vals[k].append(s[k])
        for k in KEYS:
            v = vals[k]
            if any(x is None for x in v):
                continue
            scale = 1e9 if k == "arrival" else (1.0 if k == "impulse"
                                                else 1e-6)
            o = "-"
            if len(v) >= 3:
                d1, d2 = v[-3] - v[-2], v[-2] - v[-1]
                r = sizes[-3]/sizes[-2]
                if d1 != 0 and d2 != 0 and d1*d2 > 0:
                    o = "%.2f" % (math.log(abs(d1/d2))/math.log(r))
                else:
                    o = "not monotone"
            print("| %.4g | %s | %s | %s |" % (
                z*1e6, k, " | ".join("%.6g" % (x*scale) for x in v), o))


def topCheck(case, dz, heights, amp, T, Z, end):
    print("\n4. the top: the pulse at the fixed plane Z (the delay) against "
          "the table on the moving top node, water-only column of %s, %g nm"
          % (case, dz*1e9))
    ref = lc.solve(case, heights, Z, end, dz=dz, water=True)
    moving = lc.solve(case, heights, Z, end, dz=dz, water=True,
                      fixedTop=False)
    print("| height [um] | " + " | ".join(KEYS) + " |")
    print("|---:|" + "---:|"*len(KEYS))
    for z in heights:
        _, _, e = row(moving, ref, z, amp, T)
        print("| %.4g | %s |" % (z*1e6, " | ".join(fmt(k, e[k])
                                                   for k in KEYS)))


def main():
    p = argparse.ArgumentParser()
    p.add_argument("case")
    p.add_argument("-dz", default="40e-9,20e-9,10e-9")
    p.add_argument("-rdz", type=float, default=25e-9)
    p.add_argument("-reference", default=None)
    p.add_argument("-parts", default="wall,rhoRiemann,order")
    a = p.parse_args()
    sizes = [float(x) for x in a.dz.split(",")]
    parts = a.parts.split(",")
    case = os.path.abspath(a.case)
    if "wall" in parts:
        wall(sizes)
    if not ({"rhoRiemann", "order", "top"} & set(parts)):
        return
    Z = pw.caseColumnHeight(case)
    table = pw.appliedPressure(case)
    amp, T = pw.pulseShape(table)
    probes = pw.caseProbes(case)
    top = pw.meshTop(case) or Z
    probes = [q for q in probes if 0 <= q[1] <= top*(1 + 1e-9)]
    heights = sorted({q[1] for q in probes})
    material = {q[1] for q in probes if q[0].startswith("solid")}
    end = max(q[2][-1] for q in probes)
    if "rhoRiemann" in parts:
        rhoRiemann(case, sizes, a.rdz, a.reference, heights, amp, T, Z, end)
    if "order" in parts:
        order(case, sizes, heights, material, amp, T, Z, end)
    if "top" in parts:
        topCheck(case, sizes[-1], heights, amp, T, Z, end)


if __name__ == "__main__":
    try:
        main()
    except pw.PlaneWaveError as err:
        sys.exit("layeredVerify.py: error: %s" % err)

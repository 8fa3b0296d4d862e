#!/usr/bin/python3
"""
Application
    planeWave

Description
    The exact-enough answer of a blast case: the 1D nonlinear plane wave of
    its water column (the pulse on the top face, the rigid substrate at
    z = 0), computed by rhoRiemannFoam on a column of cells of -dz with the
    case's own thermo, schemes and top/bottom conditions (neuronFsi.
    planeWave). The cell has water's bulk response and shear moduli about
    1e-7 of it, so the pressure at any height of the coupled scene is this
    wave to that order. Compared with the case's solid probes
    (postProcessing/solidProbes, pressure p<i> at the probe's height) and
    fluid probes (any probes function object sampling p): arrival, 1-ns averaged peak,
    incident plateau and impulse, scene against reference.

    Writes <case>/postProcessing/planeWave/0/:
        reference.dat   time [s], p [Pa] of the 1D answer at each height
        measures.dat    one row per probe: height, the four measures of
                        the scene and of the reference, their errors
    and prints measures.dat. With -check, exits 1 when a measure is
    outside issue 17's bounds (arrival 0.3 ns, peaks and plateau 5 %,
    impulse 3 %), naming it; -except leaves the named measures out of
    the check (they are still printed).

Usage
    planeWave [-case dir] [-Z 100e-6] [-dz 25e-9] [-endTime t]
              [-probes solid,fluid] [-check] [-except m1,m2]
              [-reference file]

    -Z          water column height [m] (the case's; default 100e-6)
    -dz         the 1D cell size [m] (default 25e-9: ten times finer
                than the preview's finest water cell)
    -endTime    [s]; default: the last time of the case's probes
    -except     measures not checked, [solid:|fluid:]<measure> (all
                probes, or the solid's or the water's only); measures:
                arrival, peak1ns, peakIncident, plateau, impulse
    -reference  reuse a reference.dat of an earlier run (same pulse,
                column and heights) instead of computing it

\\*---------------------------------------------------------------------------*/
"""

import argparse
import os
import sys

from neuronFsi import planeWave, postProcessing

BOUNDS = {"arrival": 0.3e-9, "peak1ns": 0.05, "peakIncident": 0.05,
          "plateau": 0.05, "impulse": 0.03}


def main():
    p = argparse.ArgumentParser(prog="planeWave", add_help=True)
    p.add_argument("-case", default=".")
    p.add_argument("-Z", type=float, default=100e-6)
    p.add_argument("-dz", type=float, default=25e-9)
    p.add_argument("-endTime", type=float, default=None)
    p.add_argument("-probes", default="solid,fluid")
    p.add_argument("-check", action="store_true")
    p.add_argument("-except", dest="skip", default="")
    p.add_argument("-reference", default=None)
    a = p.parse_args()
    case = os.path.abspath(a.case)
    # [(kind or None, measure)]: "peak1ns" or "fluid:peak1ns"
    skip = [tuple(k.split(":")) if ":" in k else (None, k)
            for k in a.skip.split(",") if k]
    for kind, k in skip:
        if k not in BOUNDS or kind not in (None, "solid", "fluid"):
            p.error("-except %s: not [solid:|fluid:]<measure> (measures: "
                    "%s)" % (k if kind is None else kind + ":" + k,
                             ", ".join(BOUNDS)))
    for name, v in (("-Z", a.Z), ("-dz", a.dz)):
        if not v > 0:
            p.error("%s %g m: must be positive" % (name, v))

    table = planeWave.appliedPressure(case)
    amp, T = planeWave.pulseShape(table)
    kinds = a.probes.split(",")
    probes = planeWave.caseProbes(case, "solid" in kinds, "fluid" in kinds)
    if not probes:
        sys.exit("planeWave: no solid or fluid probes in %s/postProcessing"
                 % case)
    outside = [n for n, z, _, _ in probes if not 0 <= z <= a.Z]
    if outside:
        print("planeWave: %s outside the column [0, %g] m: not compared"
              % (", ".join(outside), a.Z))
        probes = [q for q in probes if q[0] not in outside]
    heights = sorted({z for _, z, _, _ in probes})
    end = a.endTime or max(t[-1] for _, _, t, _ in probes)

    out = os.path.join(case, "postProcessing", "planeWave", "0")
    os.makedirs(out, exist_ok=True)
    if a.reference:
        wave = planeWave.readReference(a.reference)
    else:
        wave = planeWave.column(case, heights, a.Z, end, dz=a.dz)
        planeWave.writeReference(
            os.path.join(out, "reference.dat"), wave,
            "1D plane wave of %s: column %g m, cells %g m, pulse %g Pa for "
            "%g s" % (case, a.Z, a.dz, amp, T))

    rows, bad = [], []
    for name, z, t, pz in probes:
        if planeWave.arrival(wave.t, wave.at(z), amp) is None:
            print("planeWave: %s at z = %g m: the pulse has not reached it "
                  "by %g s: not compared" % (name, z, wave.t[-1]))
            continue
        s, r = planeWave.measures(t, pz, wave.t, wave.at(z), amp, T, z)
        e = planeWave.errors(s, r)
        rows.append((name, z, s, r, e))
        if s["arrival"] is None:
            bad.append("%s at z = %.4g um: never reaches half the applied "
                       "pressure (the 1D answer does at %.4g ns)"
                       % (name, z*1e6, r["arrival"]*1e9))
        for k, bound in BOUNDS.items():
            kind = "solid" if name.startswith("solid") else "fluid"
            skipped = (None, k) in skip or (kind, k) in skip
            if not skipped and e[k] is not None and abs(e[k]) > bound:
                bad.append("%s at z = %.4g um: %s error %s (bound %s)"
                           % (name, z*1e6, k, _fmt(k, e[k]),
                              _fmt(k, bound)))

    keys = ("arrival", "peak1ns", "peakIncident", "plateau", "impulse")
    unit = {"arrival": ("[ns]", 1e9), "impulse": ("[Pa s]", 1.0)}
    lines = ["# planeWave: probes of %s against the 1D plane wave (cells "
             "%g m); errors: arrival [ns], the others [%%]" % (case, a.dz),
             "# probe  z[m]  " + "  ".join(
                 "%s%s %sRef" % (k, unit.get(k, ("[MPa]",))[0], k)
                 for k in keys) + "  " + "  ".join(
                 "err%s%s" % (k[0].upper() + k[1:],
                              "[ns]" if k == "arrival" else "[%]")
                 for k in keys)]

    def v(d, k, scale):
        return "-" if d[k] is None else "%.5g" % (d[k]*scale)

    for name, z, s, r, e in rows:
        lines.append("%s %.5g  %s  %s" % (
            name.replace(" ", "_"), z,
            "  ".join("%s %s" % (v(s, k, unit.get(k, ("", 1e-6))[1]),
                                 v(r, k, unit.get(k, ("", 1e-6))[1]))
                      for k in keys),
            " ".join(v(e, k, 1e9 if k == "arrival" else 100)
                     for k in keys)))
    text = "\n".join(lines) + "\n"
    with open(os.path.join(out, "measures.dat"), "w") as f:
        f.write(text)
    sys.stdout.write(text)
    if a.check:
        if not rows:
            sys.exit("planeWave: -check, but no probe saw the pulse")
        if bad:
            sys.stdout.write("".join("FAIL %s\n" % b for b in bad))
            sys.exit(1)
        print("planeWave: every measure%s within issue 17's bounds "
              "(arrival 0.3 ns, peaks and plateau 5 %%, impulse 3 %%)"
              % (" but " + ", ".join(k if c is None else c + ":" + k
                                     for c, k in skip) if skip else ""))


def _fmt(kind, v):
    return "%.3g ns" % (v*1e9) if kind == "arrival" else "%.3g %%" % (v*100)


if __name__ == "__main__":
    try:
        main()
    except (planeWave.PlaneWaveError,
            postProcessing.ColumnFileError) as err:
        sys.exit("planeWave: %s" % err)

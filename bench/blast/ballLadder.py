#!/usr/bin/python3
"""von Mises at a point and over a ball, against the exact uniaxial answer,
along a ladder of solid meshes (docs/results/blastPlaneWave.md, "von Mises
at a point: an isochoric lateral strain, and a ball of 0.5 um"; not a
test).

Usage: ballLadder.py [-reference FILE] H=DIR [H=DIR ...]

Each DIR a run of bench/blast/transparentCell.sh (the transparent cell:
its exact answer is the water-only 1D column everywhere) with the probes
of bench/blast/ballProbes.override, after its `planeWave -check`; H its
solid element size [m] (-cell); a run without its own
postProcessing/planeWave/0/reference.dat (planeWave -reference) takes
FILE's. Per probe and run it prints:

  - the scene's von Mises 1-ns peak and its error against the exact one:
    a point probe's at its material point (reference.dat's rhoM_z
    columns, neuronFsi.planeWave.uniaxialResponse with the probe region's
    material); a ball probe's (solidProbes.dat header "the mean over the
    region within radius R") the same response averaged over the ball's
    heights, weighted by the disc's chord sqrt(R^2 - (z - z0)^2) at the
    band* probes' heights (trapezoid over z0 + k 0.125 um, |k| <= 4 R /
    0.5 um: 9 heights for R = 0.5 um, 5 for 0.25 um; exact
    for the balls inside one region; for a ball cut by the interface
    (ballFig10*) the full disc's weights, an approximation);
  - the split of that error: uniaxial(J) = the exact uniaxial response
    to the scene's own dilatation history J(t) (the volumetric part: the
    density history), and vM/uniaxial(J) (the rest: a deformation that is
    not uniaxial), with the lateral strain ln J - ln|F e_z| at the peak
    (uniaxial strain: 0);
then per probe, from the three finest runs, the observed order p and the
Richardson value of the von Mises 1-ns peak (neuronFsi.convergence's
threeLevel: none if the changes alternate) and its error against the
exact answer.
"""
import os
import sys

import numpy as np

from neuronFsi import script  # noqa: E402
script.guard()  # an input's error: one line, exit 1 (adv53 u12)
from neuronFsi import convergence, planeWave, postProcessing

LOG = "solidProbes/solidProbes.dat"


def peak1ns(t, v, sign=1):
    _, m = planeWave.runningMean(np.asarray(t), np.asarray(v), 1e-9)
    return m.max() if sign > 0 else m.min()


def material(ref, z0):
    """The reference's material point nearest height z0 (within 1 nm)."""
    z = min(ref.material, key=lambda k: abs(k - z0))
    if abs(z - z0) > 1e-9:
        sys.exit("ballLadder.py: no material point at %g m in the reference"
                 " (nearest %g m)" % (z0, z))
    return ref.material[z]


def radii(case):
    """Each probe's radius [m] (0: a point) from the file's header."""
    return [q["radius"] for q in postProcessing.probes(case, LOG)]


def run(arg, reference=None, verify=True):
    """One level H=CASE; verify=False: solidProbes.dat of a writer without
    result digests (bench/solid/exactTraction, the solid alone: its
    outputs are its ladder's own scratch folders), read as it is."""
    h, d = script.labelled(arg, "H=CASE")
    case = d if os.path.isdir(os.path.join(d, "postProcessing")) \
        else os.path.join(d, "axisymmetricPreview")
    own = os.path.join(case, "postProcessing", "planeWave", "0",
                       "reference.dat")
    if not os.path.exists(own) and reference is None:
        sys.exit("ballLadder.py: %s: no reference.dat: give -reference FILE"
                 % case)
    ref = planeWave.readReference(own if os.path.exists(own) else reference)
    probes = postProcessing.probes(case, LOG)
    a = postProcessing.series(case, LOG, verify=verify)
    n = len(probes)
    t = a[:, 0]
    bands = sorted(q["point"][1] for q in probes
                   if q["name"].startswith("band") or q["name"] == "cytoC")
    mats = {}
    out = {}
    for i, q in enumerate(probes):
        region = q["region"]
        if region not in mats:
            mats[region] = planeWave.solidMaterial(case, region)
        rho0, mu0, br = mats[region]
        vm = a[:, 1 + 5*i + 1]
        lnJ = a[:, 1 + 5*i + 2]
        ez = a[:, 1 + 5*n + 2*i]
        _, vmJ = planeWave.uniaxialResponse(t, rho0/np.exp(lnJ), rho0, mu0,
                                            br)
        z0 = q["point"][1]
        R = q["radius"]
        if R > 0:
            zs = [z for z in bands if abs(z - z0) <= R + 1e-9]
            if len(zs) < 5:
                sys.exit("ballLadder.py: %s: %d band heights within %g m of "
                         "%g m, fewer than 5 (bench/blast/ballProbes.override)"
                         % (case, len(zs), R, z0))
            w = np.sqrt(np.maximum(R*R - (np.array(zs) - z0)**2, 0))
            w[1:-1] *= 2          # trapezoid: ends half
            w /= w.sum()
            resp = [planeWave.uniaxialResponse(
                ref.t, material(ref, z)["rho"], rho0, mu0, br) for z in zs]
            vmRef = sum(wk*rk[1] for wk, rk in zip(w, resp))
            ezRef = sum(wk*rk[0] for wk, rk in zip(w, resp))
        else:
            ezRef, vmRef = planeWave.uniaxialResponse(
                ref.t, material(ref, z0)["rho"], rho0, mu0, br)
        # the lateral strain at the von Mises 1-ns peak
        tc, mv = planeWave.runningMean(t, vm, 1e-9)
        tp = tc[np.argmax(mv)]
        lat = np.interp(tp, t, lnJ - ez)
        v = peak1ns(t, vm)
        vr = peak1ns(ref.t, vmRef)
        vj = peak1ns(t, vmJ)
        out[q["name"]] = dict(region=region, point=q["point"], R=R, vm=v,
                              ref=vr, vmJ=vj, lateral=lat,
                              strain=peak1ns(t, ez, -1),
                              strainRef=peak1ns(ref.t, ezRef, -1),
                              lnJ=peak1ns(t, lnJ, -1))
    return float(h), out


def main():
    args = sys.argv[1:]
    reference = None
    if args[:1] == ["-reference"] and len(args) > 1:
        reference, args = args[1], args[2:]
    if not args:
        sys.exit(__doc__)
    runs = sorted((run(a, reference) for a in args), key=lambda x: -x[0])
    names = [k for k in runs[0][1] if not k.startswith("band")]
    print("| probe (region; r, z [um]; R [um]) | H [um] | von Mises 1-ns "
          "peak [Pa]: scene / exact | error | uniaxial(J) against exact "
          "(volumetric) | vM / uniaxial(J) (not uniaxial) | lateral strain "
          "ln J - ln F_zz at the peak | ln J 1-ns peak |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|")
    for k in names:
        for h, out in runs:
            r = out.get(k)
            if r is None:
                continue
            print("| %s (%s; %.3f, %.3f; %g) | %g | %.4f / %.4f | %+.2f %% | "
                  "%+.2f %% | %+.2f %% | %+.2e | %.5f |"
                  % (k, r["region"], r["point"][0]*1e6, r["point"][1]*1e6,
                     r["R"]*1e6, h*1e6, r["vm"], r["ref"],
                     100*(r["vm"]/r["ref"] - 1), 100*(r["vmJ"]/r["ref"] - 1),
                     100*(r["vm"]/r["vmJ"] - 1), r["lateral"], r["lnJ"]))
    if len(runs) < 3:
        return
    print()
    print("| probe | runs (H [um]) | changes | observed order p | Richardson "
          "value [Pa] | its error against the exact | the finest's error "
          "against the Richardson value |")
    print("|---|---|---|---:|---:|---:|---:|")
    for k in names:
        lv = [(h, out[k]) for h, out in runs if k in out][-3:]
        if len(lv) < 3:
            continue
        vs = [r["vm"] for _, r in lv]
        c = convergence.threeLevel([h for h, _ in lv], vs)
        v0, p = c.extrapolated, c.p
        ref = lv[-1][1]["ref"]
        print("| %s | %s | %s | %s | %s | %s | %s |"
              % (k, ", ".join("%g" % (h*1e6) for h, _ in lv),
                 " / ".join("%+.2f %%" % (100*(vs[j + 1]/vs[j] - 1))
                            for j in range(2)),
                 "-" if p is None else "%.2f" % p,
                 "-" if v0 is None else "%.4f" % v0,
                 "-" if v0 is None else "%+.2f %%" % (100*(v0/ref - 1)),
                 "-" if v0 is None else "%+.2f %%" % (100*(vs[-1]/v0 - 1))))


if __name__ == "__main__":
    main()

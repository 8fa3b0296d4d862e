#!/usr/bin/python3
"""Where the 3D quarter's flow after the pulse lives (issue 17 item 6;
docs/results/blast3D.md, "What makes the rest flow in 3D"); not a test.

    bench/blast/residualFlow3D.py CASE [--after 7.5e-8] [--fluid T ...]

CASE: a finished run of tutorials/blast/quarter3D (hexahedral cell,
solid/solid.h5 with the states at the case's write times). In the exact
answer every particle is at rest once the pulse and its echo have passed
(F = I, v = 0), so all of the motion below is error.

Solid, per written step from --after on: the kinetic energy (lumped
masses rho0 V/8 per element and node, rho0 = 1000 kg/m^3 for every
region: all three have water's density in the tutorial's materials) and
its split
  - into the axisymmetric part (the azimuthal mean of v_r, v_theta, v_z
    over the nodes of each (r, z) bin of 0.7 um, r = sqrt(x^2 + y^2))
    and the rest (what depends on the azimuth theta = atan2(y, x));
  - by the node's zone: the pole cap (r < 2 um), the symmetry planes'
    strips (theta < 10 deg or > 80 deg, r >= 2 um), the O-grid's
    diagonal (35-55 deg, r >= 2 um), the others;
  - the kinetic energy's ratio to the previous step (its growth or decay
    rate: an instability would grow).
Then at the last step the azimuthal profile: mean speed in theta bins of
15 deg over the nodes with r >= 2 um.

--fluid T ...: the water's kinetic energy at those OpenFOAM times (cell
volumes and centres from `postProcess -funcs '(writeCellCentres
writeCellVolumes)'`, run in a scratch copy when missing) by zone: the band
within 1.5 um of the cell (ellipsoidal distance d < 1.2), split as the
solid's by azimuth zone; the rest of the inner box (z < 12 um); the
column above (12-20 um; the planeWaveInflow top at 20 um), and the
axisymmetric share of the band's kinetic energy.
"""

import argparse
import os
import shutil
import subprocess
import sys
import tempfile

import h5py
import numpy as np

from neuronFsi import foamField as ff

RHO = 1000.0
A, H = 8.4e-6, 7.9e-6         # the cell's semi-axes (radius, height) [m]


def hexVolumes(X, C):
    """Volumes of the hexahedra (gmsh order) by the 2x2x2 Gauss rule."""
    g = 1/np.sqrt(3)
    V = np.zeros(len(C))
    for a in (-g, g):
        for b in (-g, g):
            for c in (-g, g):
                xi = np.array([[-1, -1, -1], [1, -1, -1], [1, 1, -1],
                               [-1, 1, -1], [-1, -1, 1], [1, -1, 1],
                               [1, 1, 1], [-1, 1, 1]], float)
                dN = 0.125*xi*np.stack([(1 + xi[:, 1]*b)*(1 + xi[:, 2]*c),
                                        (1 + xi[:, 0]*a)*(1 + xi[:, 2]*c),
                                        (1 + xi[:, 0]*a)*(1 + xi[:, 1]*b)],
                                       axis=1)
                J = np.einsum("enx,nk->exk", X[C], dN)
                V += np.linalg.det(J)
    return V


def cylindricalParts(P, v):
    r = np.hypot(P[:, 0], P[:, 1])
    th = np.arctan2(P[:, 1], P[:, 0])
    er = np.stack([np.cos(th), np.sin(th), 0*th], 1)
    et = np.stack([-np.sin(th), np.cos(th), 0*th], 1)
    return r, np.degrees(th), (v*er).sum(1), (v*et).sum(1), v[:, 2]


def axisymmetricShare(P, v, m, b=0.7e-6):
    """Kinetic energy of the azimuthal mean per (r, z) bin, of the rest."""
    r, _, vr, vt, vz = cylindricalParts(P, v)
    key = np.floor(r/b).astype(int)*100000 + np.floor(P[:, 2]/b).astype(int)
    ka = kn = 0.0
    for k in np.unique(key):
        s = key == k
        w = m[s]/m[s].sum()
        for c in (vr, vt, vz):
            mean = (w*c[s]).sum()
            ka += 0.5*m[s].sum()*mean**2
            kn += 0.5*(m[s]*(c[s] - mean)**2).sum()
    return ka, kn


def zones(P):
    r, th, *_ = cylindricalParts(P, np.zeros_like(P))
    z = np.full(len(P), "other", dtype=object)
    z[(th >= 35) & (th <= 55)] = "diagonal"
    z[(th < 10) | (th > 80)] = "symmetry"
    z[r < 2e-6] = "pole"
    return z


NAMES = ("pole", "symmetry", "diagonal", "other")


def solid(case, after):
    with h5py.File(os.path.join(case, "solid", "solid.h5"), "r") as h5:
        X = h5["mesh/coordinates"][()]
        C = h5["mesh/connectivity"][()]
        keys = sorted(h5["steps"], key=int)
        steps = [(h5["steps"][k].attrs["time"], h5["steps"][k]["velocity"][()])
                 for k in keys if h5["steps"][k].attrs["time"] >= after]
    if C.shape[1] != 8:
        sys.exit("residualFlow3D.py: hexahedral cell meshes only")
    m = np.zeros(len(X))
    np.add.at(m, C.ravel(), np.repeat(RHO*hexVolumes(X, C)/8, 8))
    z = zones(X)
    share = {n: m[z == n].sum()/m.sum() for n in NAMES}
    print("solid: %d nodes, mass %.4g kg (quarter); mass shares: %s"
          % (len(X), m.sum(), ", ".join("%s %.3f" % (n, share[n])
                                         for n in NAMES)))
    print("t [ns] | KE [J] | ratio to previous | axisymmetric / rest [J] "
          "| KE shares %s | KE per mass share %s"
          % ("/".join(NAMES), "/".join(NAMES)))
    prev = None
    for t, v in steps:
        ke = 0.5*m*(v*v).sum(1)
        K = ke.sum()
        ka, kn = axisymmetricShare(X, v, m)
        sh = [ke[z == n].sum()/K for n in NAMES]
        print("%7.2f | %.4g | %s | %.3g / %.3g | %s | %s"
              % (t*1e9, K, "%.3f" % (K/prev) if prev else "  -  ", ka, kn,
                 " ".join("%.3f" % s for s in sh),
                 " ".join("%.2f" % (s/share[n])
                          for s, n in zip(sh, NAMES))))
        prev = K
    t, v = steps[-1]
    r, th, vr, vt, vz = cylindricalParts(X, v)
    sp = np.linalg.norm(v, axis=1)
    print("at %.2f ns, nodes with r >= 2 um: theta bin [deg]: mean speed, "
          "v_r, v_theta, v_z [mm/s] (nodes)" % (t*1e9))
    for lo in range(0, 90, 15):
        s = (r >= 2e-6) & (th >= lo) & (th < lo + 15 + 1e-9*(lo == 75))
        print("   %2d-%2d: %.2f, %+.2f, %+.2f, %+.2f (%d)"
              % (lo, lo + 15, 1e3*sp[s].mean(), 1e3*vr[s].mean(),
                 1e3*vt[s].mean(), 1e3*vz[s].mean(), s.sum()))


def cellData(case, t):
    d = os.path.join(case, t)
    if not (os.path.exists(os.path.join(d, "C"))
            and os.path.exists(os.path.join(d, "V"))):
        tmp = tempfile.mkdtemp()
        try:
            for s in ("constant", "system", t):
                shutil.copytree(os.path.join(case, s), os.path.join(tmp, s))
            subprocess.run(["postProcess", "-case", tmp, "-time", t,
                            "-funcs", "(writeCellCentres writeCellVolumes)"],
                           check=True, capture_output=True)
            C = ff.internalField(os.path.join(tmp, t, "C"))
            V = ff.internalField(os.path.join(tmp, t, "V"))
        finally:
            shutil.rmtree(tmp)
    else:
        C = ff.internalField(os.path.join(d, "C"))
        V = ff.internalField(os.path.join(d, "V"))
    return C, V


def fluid(case, times):
    for t in times:
        C, V = cellData(case, t)
        U = ff.internalField(os.path.join(case, t, "U"))
        rho = ff.internalField(os.path.join(case, t, "rho")) \
            if os.path.exists(os.path.join(case, t, "rho")) else RHO
        m = rho*V
        ke = 0.5*m*(U*U).sum(1)
        d = np.sqrt((C[:, 0]**2 + C[:, 1]**2)/A**2 + C[:, 2]**2/H**2)
        band = d < 1.2
        inner = (~band) & (C[:, 2] < 12e-6)
        column = C[:, 2] >= 12e-6
        z = zones(C)
        K = ke.sum()
        print("water at %s s (%d cells): KE %.4g J; band d < 1.2 %.3f, "
              "rest of z < 12 um %.3f, z >= 12 um %.3f of it"
              % (t, len(C), K, ke[band].sum()/K, ke[inner].sum()/K,
                 ke[column].sum()/K))
        Kb = ke[band].sum()
        mb = m[band].sum()
        print("   band: KE %.4g J (solid-comparable); by zone %s: KE share "
              "%s, mass share %s" % (Kb, "/".join(NAMES), " ".join(
                  "%.3f" % (ke[band & (z == n)].sum()/Kb) for n in NAMES),
                  " ".join("%.3f" % (m[band & (z == n)].sum()/mb)
                           for n in NAMES)))
        ka, kn = axisymmetricShare(C[band], U[band], m[band])
        print("   band: axisymmetric / rest %.3g / %.3g J" % (ka, kn))


def main():
    a = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    a.add_argument("case")
    a.add_argument("--after", type=float, default=7.5e-8)
    a.add_argument("--fluid", nargs="+", default=None)
    o = a.parse_args()
    case = os.path.abspath(o.case)
    if o.fluid:
        return fluid(case, o.fluid)
    return solid(case, o.after)


if __name__ == "__main__":
    main()

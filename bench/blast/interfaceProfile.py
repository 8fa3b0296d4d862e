#!/usr/bin/python3
"""Von Mises and longitudinal strain across the cell's interfaces against
the exact answer (issue 17 item 8, "localisation at the interfaces"; not a
test).

    bench/blast/interfaceProfile.py CASE [--time 65.5e-9] [--band 0.3e-6]
                                    [--out PNG]

CASE: a blast preview case (r-z) with solid/solid.h5, run with the pulse on
a planeWaveInflow or a classic top. Along the ray from the substrate's
centre (r, z) = (0, 0) through the Fig. 10 point (3.8461, 4.108) um, which
crosses the cytoplasm-nucleus interface at that point and the membrane
further out, every element whose centroid lies within --band of the ray:
its von Mises stress and its strain ln(stretch_z) (from the element's
J and the displacement gradient: the zz component of ln V, small-strain
form eps_zz = du_z/dz here) at the write nearest --time, against the
exact answer of the plane wave at the element's height: uniaxial strain
with the water's density there (planeWave.column, 50 nm cells, the
case's own pulse and column) and the region's neo-Hookean + Maxwell law
(planeWave.uniaxialResponse). In the exact answer the strain is
continuous and von Mises jumps by the ratio of the shear moduli; any
concentration beyond that jump is the scene's. Writes the profile to
stdout and the figure to --out (default <CASE>/interfaceProfile.png).
Region numbers of solid.h5 as in bench/blast/solidStrainNoise.py.
"""
import argparse
import os
import sys

import numpy as np

from neuronFsi import bench, planeWave
from neuronFsi.solidResults import SolidResults

FIG10 = np.array([3.8461e-6, 4.108e-6])
NAMES = {0: "nucleus", 1: "cytoplasm", 2: "membrane"}


def elementGradientZ(X, u, conn):
    """du_z/dz at each bilinear quad's centroid (r-z coordinates)"""
    out = np.empty(len(conn))
    dN = 0.25*np.array([[-1, -1], [1, -1], [1, 1], [-1, 1]], float)
    for e, nodes in enumerate(conn):
        x = X[nodes, :2]
        J = dN.T @ x                      # d(r,z)/d(xi,eta) transposed
        G = np.linalg.solve(J, dN.T)      # d N / d(r,z), 2 x 4
        out[e] = G[1] @ u[nodes, 1]
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("case")
    ap.add_argument("--time", type=float, default=65.5e-9)
    ap.add_argument("--band", type=float, default=0.3e-6)
    ap.add_argument("--out")
    a = bench.parse(ap)
    case = a.case
    with SolidResults(os.path.join(case, "solid", "solid.h5")) as s:
        k = s.nearest(a.time)
        t = s.time(k)
        X = s.mesh("coordinates")
        conn = s.mesh("connectivity")
        region = s.mesh("region") if "region" in s.file["mesh"] else \
            s.field(k, "region")
        u = s.field(k, "displacement")
        vm = s.field(k, "vonMises")
    if conn.shape[1] != 4:
        sys.exit("interfaceProfile: an r-z case (bilinear quads) is needed")
    centroid = X[conn, :2].mean(axis=1)
    d = FIG10/np.linalg.norm(FIG10)
    along = centroid @ d
    off = np.abs(centroid[:, 0]*d[1] - centroid[:, 1]*d[0])
    sel = np.where(off < a.band)[0]
    sel = sel[np.argsort(along[sel])]
    ezz = elementGradientZ(X, u, conn)
    # the exact answer at each selected element's height
    heights = sorted(set(np.round(centroid[sel, 1], 9)))
    Z = planeWave.inflowColumnHeight(case) or 100e-6
    wave = planeWave.column(case, heights, Z, t + 1e-9, dz=50e-9)
    rows = []
    for e in sel:
        z = np.round(centroid[e, 1], 9)
        name = NAMES.get(int(region[e]), str(region[e]))
        rho = np.interp(t, wave.t, wave.densityAt(z))
        if name == "membrane":
            vmRef = np.nan
        else:
            rho0, mu0, branches = planeWave.solidMaterial(case, name)
            _, vmx = planeWave.uniaxialResponse(
                wave.t, wave.densityAt(z), rho0, mu0, branches)
            vmRef = np.interp(t, wave.t, vmx)
        ezRef = np.log(1000.0/rho)
        rows.append((along[e], name, vm[e], vmRef, ezz[e], ezRef))
    print("# interfaceProfile: %s at t = %.4g ns, elements within %g um of "
          "the ray through the Fig. 10 point" % (case, t*1e9, a.band*1e6))
    print("# s[um] region vonMises[Pa] vonMisesExact[Pa] strainZ[-] "
          "strainZExact[-]")
    for r in rows:
        print("%.4f %s %.5g %.5g %.5g %.5g" % (r[0]*1e6, *r[1:]))
    # behind the front: where the exact von Mises is within 10 % of its
    # largest on the ray in the region
    for name in ("nucleus", "cytoplasm"):
        rr = [r for r in rows if r[1] == name]
        if not rr:
            continue
        vmS = np.array([r[2] for r in rr])
        vmX = np.array([r[3] for r in rr])
        ezS = np.array([r[4] for r in rr])
        ezX = np.array([r[5] for r in rr])
        m = vmX >= 0.9*vmX.max()
        rel = vmS[m]/vmX[m] - 1
        print("# %s behind the front (exact von Mises >= 90 %% of its largest"
              " on the ray): %d of %d elements, von Mises vs exact rms %.1f "
              "%%, mean %+.1f %%, range %+.1f to %+.1f %%; strain mean %+.1f "
              "%%" % (name, m.sum(), len(rr), 100*np.sqrt(np.mean(rel**2)),
                      100*rel.mean(), 100*rel.min(), 100*rel.max(),
                      100*np.mean(ezS[m]/ezX[m] - 1)))
        if name == "cytoplasm":
            last = rr[-5:]
            print("# cytoplasm's last %d elements before the membrane (s %.2f"
                  "-%.2f um): von Mises vs exact %s %%" % (
                      len(last), last[0][0]*1e6, last[-1][0]*1e6,
                      " ".join("%+.1f" % (100*(r[2]/r[3] - 1))
                               for r in last)))
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(1, 2, figsize=(11, 4))
    s_ = np.array([r[0] for r in rows])*1e6
    for i, (lab, col, ref) in enumerate((("von Mises [Pa]", 2, 3),
                                         ("strain_z ~ du_z/dz [-]", 4, 5))):
        ax[i].plot(s_, [r[col] for r in rows], "o", ms=3, label="scene "
                   "(elements)")
        ax[i].plot(s_, [r[ref] for r in rows], "-", label="exact (plane "
                   "wave, uniaxial strain)")
        ax[i].axvline(np.linalg.norm(FIG10)*1e6, color="grey", lw=0.8,
                      ls=":")
        ax[i].set_xlabel("distance from (0, 0) along the ray through the "
                         "Fig. 10 point [um]")
        ax[i].set_ylabel(lab)
        ax[i].legend(fontsize=8)
    fig.suptitle("Across the interfaces at t = %.2f ns (dotted: the "
                 "cytoplasm-nucleus interface point)" % (t*1e9))
    fig.tight_layout()
    out = a.out or os.path.join(case, "interfaceProfile.png")
    fig.savefig(out, dpi=110)
    print("# wrote %s" % out)


if __name__ == "__main__":
    bench.main(main)

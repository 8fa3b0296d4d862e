#!/usr/bin/python3
"""Von Mises and longitudinal strain across the cell's interfaces against
the exact answer (issue 17 item 8, "localisation at the interfaces"; not a
test).

    bench/blast/interfaceProfile.py CASE [--time 65.5e-9] [--band 0.3e-6]
                                    [--out PNG]
    bench/blast/interfaceProfile.py CASE --normal [--time 65.5e-9]
                                    [--band 0.2e-6] [--half 1.5e-6]
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

--normal: profiles normal to each interface (cytoplasm-nucleus,
membrane-cytoplasm) at three points of it: its top on the axis (the
interface faces the wave), where the ray through the Fig. 10 point (probe
0) meets it (oblique) and its point farthest from the axis (the side,
along the wave); neuronFsi.paper.interfaceNormalProfile: the normal of
the line fitted to the interface's sides within 0.6 um, in the deformed
configuration at the write, every element whose centroid is within
--band of the normal line and within --half of the interface. Each
element's von Mises and strain_z = ln F_zz (damageIndicators.
centreGradient) against the exact answer at the element's current height
(the plane wave on a 50 nm grid of heights, 50 nm cells, interpolated
linearly; nucleus and cytoplasm only: the membrane's volumetric law is
not the water's). Prints per profile the element next to the interface
on each side and the mean over 0.5 um < |s| <= --half, as scene / exact.
"""
import argparse
import os
import sys

import numpy as np

from neuronFsi import script  # noqa: E402
# an input's error is one line, not a traceback (adv52 p18)
script.guard()
from neuronFsi import bench, damageIndicators, indentationPlots, paper, \
    planeWave, postProcessing
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
    ap.add_argument("--normal", action="store_true")
    ap.add_argument("--half", type=float, default=1.5e-6)
    ap.add_argument("--until", type=float)
    a = bench.parse(ap)
    case = a.case
    if a.normal:
        return normalProfiles(case, a.time, 0.2e-6 if a.band == 0.3e-6
                              else a.band, a.half, a.out, a.until)
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


INTERFACES = ("cytoplasm-nucleus", "membrane-cytoplasm")
GRID = 50e-9        # the exact answer's heights and cells [m]


def exactByHeight(case, t, top):
    """{region: (heights [m], times [s], von Mises [Pa], strain_z [-])}:
    the plane wave to time t on a grid of heights from GRID/2 to top, the
    histories [time, height]"""
    heights = list(np.arange(GRID/2, top, GRID))
    Z = planeWave.inflowColumnHeight(case) or 100e-6
    wave = planeWave.column(case, heights, Z, t + 1e-9, dz=GRID)
    out = {}
    for name in ("nucleus", "cytoplasm"):
        rho0, mu0, branches = planeWave.solidMaterial(case, name)
        vm, ez = [], []
        for z in heights:
            e, v = planeWave.uniaxialResponse(wave.t, wave.densityAt(z),
                                              rho0, mu0, branches)
            vm.append(v)
            ez.append(e)
        out[name] = (np.array(heights), wave.t, np.array(vm).T,
                     np.array(ez).T)
    return out


def exactAt(exact, name, t, z):
    """The exact (von Mises, strain_z) of region name at time t [s] and
    the heights z [m] (nan for a region without one)"""
    if name not in exact:
        return np.full(len(z), np.nan), np.full(len(z), np.nan)
    h, tt, vm, ez = exact[name]
    k = np.searchsorted(tt, t)
    k = min(max(k, 1), len(tt) - 1)
    w = (t - tt[k - 1])/(tt[k] - tt[k - 1])
    v = (1 - w)*vm[k - 1] + w*vm[k]
    e = (1 - w)*ez[k - 1] + w*ez[k]
    return np.interp(z, h, v), np.interp(z, h, e)


def normalProfiles(case, time, band, half, out, until=None):
    h5 = os.path.join(case, "solid", "solid.h5")
    f = indentationPlots.fields(case, time, h5=h5, tolerance=None)
    t, X, conn, region, u, names = (f.t, f.X, f.conn, f.region, f.u,
                                    f.names)
    if conn.shape[1] != 4:
        sys.exit("interfaceProfile: an r-z case (bilinear quads) is needed")
    x = X + u
    # the writes compared: the one at --time, or every write up to --until
    # (the largest of each element over them, and of the exact answer at
    # the element's height at each)
    with SolidResults(h5) as r:
        times = [tk for tk in r.times() if tk <= until] if until \
            else [t]
    tEnd = max(times)
    zTop = 0
    snaps = []
    for tk in times:
        fk = indentationPlots.fields(case, tk, h5=h5, tolerance=None)
        zk = (fk.X + fk.u)[conn, 1].mean(axis=1)
        zTop = max(zTop, zk.max())
        snaps.append((fk.t, fk.vm, np.log(damageIndicators.centreGradient(
            X, conn, fk.u)[:, 1, 1]), zk))
    exact = exactByHeight(case, tEnd, zTop + 0.5e-6)
    vm = np.max([sn[1] for sn in snaps], axis=0)
    ez = np.min([sn[2] for sn in snaps], axis=0)   # most compressive
    vmX = np.full(len(conn), np.nan)
    ezX = np.full(len(conn), np.nan)
    for rn in ("nucleus", "cytoplasm"):
        m = np.array([names[r] == rn for r in region])
        vv = [exactAt(exact, rn, tk, zk[m]) for tk, _, _, zk in snaps]
        vmX[m] = np.max([v[0] for v in vv], axis=0)
        ezX[m] = np.min([v[1] for v in vv], axis=0)
    probe = postProcessing.probes(case)[0]["point"][:2]
    wheres = (("top", "top (on the axis)"),
              (probe, "on the ray through the Fig. 10 point"),
              ((1.0, 0.25), "on the ray at 14 deg (the side)"))
    what = ("at t = %.4g ns" % (t*1e9) if not until else
            "largest over the %d writes %.4g-%.4g ns (strain: most "
            "negative)" % (len(times), min(times)*1e9, tEnd*1e9))
    print("# interfaceProfile --normal: %s %s; profiles at %.4g ns, "
          "elements within %g um of the normal line, %g um either side; "
          "ratios scene / exact" % (case, what, t*1e9, band*1e6, half*1e6))
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    rows = []
    for j, iface in enumerate(INTERFACES):
        for i, (where, label) in enumerate(wheres):
            p = paper.interfaceNormalProfile(x, conn, region, names, iface,
                                             where, half=half, band=band)
            e, sd = p["elements"], p["s"]
            reg = [names[r] for r in region[e]]
            o, n = p["origin"], p["normal"]
            print("# %s, %s: point (r, z) = (%.3f, %.3f) um, normal (%.3f, "
                  "%.3f), %d elements" % (iface, label, o[0]*1e6, o[1]*1e6,
                                          n[0], n[1], len(e)))
            outer, _, inner = iface.partition("-")
            for side, rn, sign in (("outer", outer, 1), ("inner", inner,
                                                         -1)):
                m = np.array([r == rn for r in reg]) & (sign*sd > 0)
                if not m.any():
                    continue
                adj = np.nonzero(m)[0][np.argmin(np.abs(sd[m]))]
                far = m & (np.abs(sd) > 0.5e-6)
                ea, ef = e[adj], e[far]
                if np.isnan(vmX[ea]):
                    print("#   %s (%s): next to the interface s = %+.2f um"
                          " von Mises %.3g Pa (no exact answer); 0.5-%.1f "
                          "um away mean %.3g Pa" % (
                              rn, side, sd[adj]*1e6, vm[ea], half*1e6,
                              np.mean(vm[ef]) if far.any() else np.nan))
                    continue
                print("#   %s (%s): next to the interface s = %+.2f um von "
                      "Mises %.3g Pa (exact %.3g, x%.3f), strain %.4g (exact"
                      " %.4g, x%.3f); 0.5-%.1f um away (%d elements) von "
                      "Mises x%.3f, strain x%.3f" % (
                          rn, side, sd[adj]*1e6, vm[ea], vmX[ea],
                          vm[ea]/vmX[ea], ez[ea], ezX[ea], ez[ea]/ezX[ea],
                          half*1e6, far.sum(),
                          np.mean(vm[ef]/vmX[ef]) if far.any() else np.nan,
                          np.mean(ez[ef]/ezX[ef]) if far.any() else np.nan))
            rows.append((i, j, iface, label, e, sd, reg))
    fig, ax = plt.subplots(len(wheres), 4, figsize=(17, 10))
    for i, j, iface, label, e, sd, reg in rows:
        for c, (vals, ref, lab) in enumerate(
                ((vm[e], vmX[e], "von Mises [Pa]"),
                 (ez[e], ezX[e], "strain_z = ln F_zz [-]"))):
            a_ = ax[i, 2*j + c]
            for rn, col in (("nucleus", "C0"), ("cytoplasm", "C1"),
                            ("membrane", "C3")):
                m = np.array([r == rn for r in reg])
                if not m.any():
                    continue
                a_.plot(sd[m]*1e6, vals[m], "o", ms=3, color=col,
                        label="%s (elements)" % rn)
                if np.isfinite(ref[m]).any():
                    a_.plot(sd[m]*1e6, ref[m], "-", color=col, lw=1,
                            alpha=0.7)
            a_.axvline(0, color="grey", lw=0.8, ls=":")
            a_.set_title("%s, %s" % (iface, label), fontsize=9)
            a_.set_xlabel("s along the normal, + outwards [um]")
            a_.set_ylabel(lab)
            a_.grid(alpha=0.3)
            if i == 0:
                a_.legend(fontsize=7)
    fig.suptitle("Profiles normal to the interfaces, %s: elements (dots) "
                 "and the exact plane wave (lines; nucleus and cytoplasm)"
                 % what)
    fig.tight_layout()
    out = out or os.path.join(case, "interfaceNormalProfiles.png")
    fig.savefig(out, dpi=80)
    print("# wrote %s" % out)


if __name__ == "__main__":
    bench.main(main)

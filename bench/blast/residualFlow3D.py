#!/usr/bin/python3
"""Where the 3D quarter's flow after the pulse lives (issue 17 item 6;
docs/results/blast3D.md, "What makes the rest flow in 3D"); not a test.

    bench/blast/residualFlow3D.py CASE [--after 7.5e-8] [--fluid T ...]
                                       [--vorticity T ...] [--faces]
                                       [--zones T ...] [--front]
                                       [--drive T T ...]

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

--vorticity T ...: where the water's vorticity is (exact: none; an
inviscid water keeps what the scheme makes): at each time the enstrophy
(1/2 |curl U|^2 V, OpenFOAM's vorticity function object) by bins of r
and z, its share in the cells of each band of the mesh's largest face
non-orthogonality (checkMesh -writeFields nonOrthoAngle, on the case's
constant mesh), and the twelve cells that hold the most, with their
position, size V^(1/3), |curl U| and non-orthogonality; the crest of the
pressure (where the front is) for orientation.

--zones T ...: the water's lateral flow (exact: none; lateral = the x, y
components, across the wave's z) and its enstrophy at each time (a
time series when given many), over the mesh's zones: the O-grid (inside
the inner box [0, a + margin]^2 x [0, H + margin], margin
neuronFsi.cellRefinement.innerMargin's; outside the cell) split by
azimuth as the solid (pole r < 2 um, the symmetry planes' strips, the
diagonal seam 35-55 deg, the others) and by the cell's largest face
non-orthogonality (below 20, 20-40, 40 deg and more: the rays from the
inner box's edges), and the Cartesian water outside the inner box; per
zone the share of the lateral kinetic energy, of the enstrophy and of
the mass, and the mass-weighted rms lateral speed; the pressure crest's
height for orientation; the lateral kinetic energy's share by bins of r
and z.

--front: the first front's steepness at the water probes
(postProcessing/fluidProbes/0/p): its arrival (10 % of the largest
pressure within 3 ns of the first 5 %), its 10-90 % rise time and that
largest pressure; a captured shock and a linear front of equal width
differ in shape, not in this number.

--drive T T ...: what acts on the water around the cell after the pulse
(docs/results/blast3D.md, "What keeps the 3D cell flowing"). At each
time, over the zones by the ellipsoidal distance d from the cell's centre
(d < 1.2, 1.2-2, d >= 2 below z = 12 um, z >= 12 um: the column up to the
inflow top): the gauge pressure's volume mean, its rms about the mean and
its extremes, the acoustic speed that rms would carry (p_rms / (rho0 c),
c from the case's water law at rest), the rms speed, the mean v_z, and
the rms of |grad p| and of |curl U|;
between consecutive times: the rms of rho dU/dt (the change over the
interval) against the rms of -grad p (the mean of the two times), and
the mean change of v_z; then the work the water does on the cell in
each interval (fsi/coupling.dat's fluidWallWork; negative: the cell
gives energy to the water). T: OpenFOAM time names, at least two.

--faces: the water's faces on the cell (patch cellInterface, from
`surfaceMeshExtract` in a scratch copy) by the polar angle of their
centre on the cell (0 at the top, atan2(r/a, z/H), a = 8.4 um, H =
7.9 um): count and mean extent along the meridian and along the azimuth.
"""

import argparse
import contextlib
import os
import shutil
import subprocess
import sys
import tempfile

import h5py
import numpy as np

from neuronFsi import script  # noqa: E402
# an input's error is one line, not a traceback (adv52 p18)
script.guard()
from neuronFsi import cellRefinement
from neuronFsi import foamField as ff
from neuronFsi import postProcessing
from neuronFsi import scratch

RHO = 1000.0
A, H = 8.4e-6, 7.9e-6         # the cell's semi-axes (radius, height) [m]


@contextlib.contextmanager
def scratchCase(case, names, empty=()):
    """A scratch copy of the entries names of case (and the empty folders
    empty), removed afterwards: the utilities run there, the case is not
    written to."""
    tmp = tempfile.mkdtemp()
    try:
        dst = os.path.join(tmp, "case")
        scratch.copyInputs(case, dst, names)
        for e in empty:
            os.makedirs(os.path.join(dst, e))
        yield dst
    finally:
        shutil.rmtree(tmp)


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
        with scratchCase(case, ("constant", "system", t)) as tmp:
            subprocess.run(["postProcess", "-case", tmp, "-time", t,
                            "-funcs", "(writeCellCentres writeCellVolumes)"],
                           check=True, capture_output=True)
            C = ff.internalField(os.path.join(tmp, t, "C"))
            V = ff.internalField(os.path.join(tmp, t, "V"))
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


def postFields(case, t, funcs):
    """Cell centres, volumes and the fields of funcs at time t, from a
    scratch copy of the case (the case is not written to)."""
    with scratchCase(case, ("constant", "system", t)) as tmp:
        subprocess.run(["postProcess", "-case", tmp, "-time", t, "-funcs",
                        "(writeCellCentres writeCellVolumes %s)"
                        % " ".join(funcs)], check=True, capture_output=True)
        return {n: ff.internalField(os.path.join(tmp, t, n))
                for n in ["C", "V"] + list(funcs) + ["p"]}


def nonOrthogonality(case):
    with scratchCase(case, ("constant", "system"), ("0",)) as tmp:
        subprocess.run(["checkMesh", "-case", tmp, "-constant",
                        "-writeFields", "(nonOrthoAngle)"], check=True,
                       capture_output=True)
        return ff.internalField(os.path.join(tmp, "constant",
                                             "nonOrthoAngle"))


def vorticity(case, times):
    no = nonOrthogonality(case)
    for t in times:
        f = postFields(case, t, ["vorticity"])
        C, V, W, p = f["C"], f["V"], f["vorticity"], f["p"]
        ens = 0.5*V*(W*W).sum(1)
        E = ens.sum()
        r = np.hypot(C[:, 0], C[:, 1])
        print("water at %s s: enstrophy %.3g m^3/s^2; pressure crest at "
              "z = %.2f um" % (t, E, C[np.argmax(p), 2]*1e6))
        print("   share by r [um] (rows) and z [um] (columns 0-4, 4-8, "
              "8-12, 12-16, 16-20):")
        for lo, hi in ((0, 5), (5, 10), (10, 14), (14, 20), (20, 30),
                       (30, 80)):
            sr = (r >= lo*1e-6) & (r < hi*1e-6)
            print("     r %2d-%2d: %s" % (lo, hi, " ".join(
                "%.3f" % (ens[sr & (C[:, 2] >= z*1e-6)
                              & (C[:, 2] < (z + 4)*1e-6)].sum()/E)
                for z in range(0, 20, 4))))
        print("   by the cell's largest face non-orthogonality [deg]: "
              "cells, enstrophy share, mean |curl U| [1/s]")
        for lo in range(0, 90, 10):
            s = (no >= lo) & (no < lo + 10)
            if s.sum():
                print("     %2d-%2d: %5d %.3f %.3g" % (
                    lo, lo + 10, s.sum(), ens[s].sum()/E,
                    np.linalg.norm(W[s], axis=1).mean()))
        print("   the cells with the most: x, y, z [um], V^(1/3) [um], "
              "|curl U| [1/s], share, non-orthogonality [deg]")
        for i in np.argsort(-ens)[:12]:
            print("     %6.2f %6.2f %6.2f  %.2f  %.3g  %.3f  %.1f"
                  % (C[i, 0]*1e6, C[i, 1]*1e6, C[i, 2]*1e6,
                     np.cbrt(V[i])*1e6, np.linalg.norm(W[i]),
                     ens[i]/E, no[i]))


def innerBox(case):
    """The O-grid's inner box (x, y, z extents) [m]."""
    margin = cellRefinement.innerMargin(case)
    return np.array([A + margin, A + margin, H + margin])


def zoneFlow(case, times):
    no = nonOrthogonality(case)
    B = innerBox(case)
    print("inner box %.2f x %.2f x %.2f um" % tuple(1e6*B))
    first = True
    for t in times:
        f = postFields(case, t, ["vorticity"])
        C, V, W, p = f["C"], f["V"], f["vorticity"], f["p"]
        U = ff.internalField(os.path.join(case, t, "U"))
        rho = ff.internalField(os.path.join(case, t, "rho")) \
            if os.path.exists(os.path.join(case, t, "rho")) else RHO
        m = rho*V
        kl = 0.5*m*(U[:, 0]**2 + U[:, 1]**2)
        ens = 0.5*V*(W*W).sum(1)
        inside = np.all(C < B, axis=1)
        z = zones(C)
        sets = [("O-grid " + n, inside & (z == n)) for n in NAMES]
        sets += [("O-grid nonortho <20", inside & (no < 20)),
                 ("O-grid nonortho 20-40", inside & (no >= 20) & (no < 40)),
                 ("O-grid nonortho >=40", inside & (no >= 40)),
                 ("outside the box", ~inside)]
        K, E, M = kl.sum(), ens.sum(), m.sum()
        if first:
            print("zones (cells): %s" % ", ".join(
                "%s (%d)" % (n, s.sum()) for n, s in sets))
            first = False
        print("t %s s: crest z %.2f um; lateral KE %.4g J, rms lateral "
              "speed %.4g m/s, enstrophy %.4g m^3/s^2; per zone: lateral "
              "KE share / enstrophy share / mass share / rms lateral "
              "speed [m/s]" % (t, 1e6*C[np.argmax(p), 2], K,
                               np.sqrt(2*K/M), E))
        for n, s in sets:
            print("   %-22s %.3f / %.3f / %.3f / %.4g"
                  % (n, kl[s].sum()/K, ens[s].sum()/E, m[s].sum()/M,
                     np.sqrt(2*kl[s].sum()/m[s].sum())))
        r = np.hypot(C[:, 0], C[:, 1])
        print("   lateral KE share by r [um] (rows) and z [um] (columns "
              "0-4, 4-8, 8-12, 12-16, 16-20):")
        for lo, hi in ((0, 5), (5, 10), (10, 14), (14, 20), (20, 30),
                       (30, 80)):
            sr = (r >= lo*1e-6) & (r < hi*1e-6)
            print("     r %2d-%2d: %s" % (lo, hi, " ".join(
                "%.3f" % (kl[sr & (C[:, 2] >= zl*1e-6)
                             & (C[:, 2] < (zl + 4)*1e-6)].sum()/K)
                for zl in range(0, 20, 4))))


def drive(case, times):
    from neuronFsi import planeWave
    c0 = planeWave.soundSpeedAtRest(case)
    F = []
    for t in times:
        f = postFields(case, t, ["grad(p)", "vorticity"])
        f["U"] = ff.internalField(os.path.join(case, t, "U"))
        f["rho"] = ff.internalField(os.path.join(case, t, "rho"))
        F.append(f)
    C, V = F[0]["C"], F[0]["V"]
    d = np.sqrt((C[:, 0]**2 + C[:, 1]**2)/A**2 + C[:, 2]**2/H**2)
    sets = [("d < 1.2", d < 1.2), ("d 1.2-2", (d >= 1.2) & (d < 2)),
            ("d >= 2, z < 12 um", (d >= 2) & (C[:, 2] < 12e-6)),
            ("z >= 12 um", C[:, 2] >= 12e-6)]
    print("zones (cells): %s; water's sound speed at rest %.1f m/s"
          % (", ".join("%s (%d)" % (n, s.sum()) for n, s in sets), c0))

    def rms(w, x):
        return np.sqrt((w*(x*x if x.ndim == 1 else (x*x).sum(1))).sum())
    for t, f in zip(times, F):
        curl = f["vorticity"]
        print("t %s s: gauge p mean, rms about it, min, max [Pa]; p_rms/"
              "(rho0 c) [m/s]; rms speed, mean v_z [m/s]; rms |grad p| "
              "[Pa/m], |curl U| [1/s]" % t)
        for n, s in sets:
            w = V[s]/V[s].sum()
            p = f["p"][s]
            m = (w*p).sum()
            sd = rms(w, p - m)
            print("   %-18s %+.3e %.3e %+.3e %+.3e; %.2e; %.4f %+.4f; "
                  "%.3e %.3e" % (
                      n, m, sd, p.min(), p.max(), sd/(RHO*c0),
                      rms(w, f["U"][s]), (w*f["U"][s][:, 2]).sum(),
                      rms(w, f["grad(p)"][s]), rms(w, curl[s])))
    for (ta, fa), (tb, fb) in zip(zip(times, F), zip(times[1:], F[1:])):
        dt = float(tb) - float(ta)
        print("%s to %s s: rms rho dU/dt, rms -grad p, rms of their "
              "difference [Pa/m]; mean change of v_z [m/s]" % (ta, tb))
        for n, s in sets:
            w = V[s]/V[s].sum()
            acc = (0.5*(fa["rho"][s] + fb["rho"][s])[:, None]
                   * (fb["U"][s] - fa["U"][s])/dt)
            gp = -0.5*(fa["grad(p)"][s] + fb["grad(p)"][s])
            print("   %-18s %.3e %.3e %.3e; %+.4f" % (
                n, rms(w, acc), rms(w, gp), rms(w, acc - gp),
                (w*(fb["U"][s][:, 2] - fa["U"][s][:, 2])).sum()))
    # the inflow top's layer: the planeWaveInflow top passes a wave going
    # up (w_up = p + rho0 c v_z) and takes the 1D column's incoming one
    # (w_down = p - rho0 c v_z), which is zero once the 1D pulse's echo
    # has left (the 1D answer at the top is at rest until the echo of the
    # physical column's top returns); for a wave meeting the top head-on
    # w_down in its layer is then what the top reflects
    ztop = C[:, 2].max()
    top = C[:, 2] > ztop - 0.3e-6
    w = V[top]/V[top].sum()
    print("the top layer (%d cells, z > %.2f um): rms of w_up = p + rho0 c "
          "v_z and of w_down = p - rho0 c v_z [Pa], their ratio"
          % (top.sum(), 1e6*(ztop - 0.3e-6)))
    for t, f in zip(times, F):
        up = f["p"][top] + RHO*c0*f["U"][top][:, 2]
        down = f["p"][top] - RHO*c0*f["U"][top][:, 2]
        print("   %s s: %.3e %.3e %.3f" % (t, rms(w, up), rms(w, down),
                                          rms(w, down)/rms(w, up)))
    log = "fsi/coupling.dat"
    if os.path.isdir(os.path.join(case, "postProcessing", "fsi")):
        d = postProcessing.series(case, log)
        k = postProcessing.names(case, log).index("fluidWallWork")
        W = np.interp([float(x) for x in times], d[:, 0], d[:, k])
        print("work of the water on the cell (fsi/coupling.dat "
              "fluidWallWork) per interval [J]: %s" % ", ".join(
                  "%s-%s: %+.3e" % (a, b, wb - wa) for a, b, wa, wb in zip(
                      times, times[1:], W, W[1:])))


def front(case):
    d = np.loadtxt(os.path.join(case, "postProcessing", "fluidProbes", "0",
                                "p"))
    t = d[:, 0]
    for k in range(1, d.shape[1]):
        p = d[:, k]
        i0 = np.argmax(p > 0.05*p.max())
        i1 = i0 + np.searchsorted(t[i0:], t[i0] + 3e-9)
        pk = p[i0:i1].max()
        a = t[np.argmax(p > 0.1*pk)]
        b = t[np.argmax(p > 0.9*pk)]
        print("water probe %d: arrival %.2f ns, rise 10-90 %% %.3f ns, "
              "largest within 3 ns %.4g MPa" % (k - 1, 1e9*a, 1e9*(b - a),
                                                1e-6*pk))


def faces(case):
    with scratchCase(case, ("constant", "system"), ("0",)) as tmp:
        subprocess.run(["surfaceMeshExtract", "-case", tmp, "-constant",
                        "-patches", "(cellInterface)", "ci.obj"],
                       check=True, capture_output=True)
        V, F = [], []
        for line in open(os.path.join(tmp, "ci_0.obj")):
            if line.startswith("v "):
                V.append([float(x) for x in line.split()[1:4]])
            elif line.startswith("f "):
                F.append([int(x.split("/")[0]) - 1
                          for x in line.split()[1:]])
    P = np.array(V)
    rows = []
    for idx in F:
        X = P[idx]
        c = X.mean(0)
        r = np.hypot(c[0], c[1])
        et = (np.array([-c[1], c[0], 0])/r if r > 1e-12
              else np.array([0, 1.0, 0]))
        n = np.array([c[0]/A**2, c[1]/A**2, c[2]/H**2])
        tm = np.cross(et, n/np.linalg.norm(n))
        tm /= np.linalg.norm(tm)
        rows.append((np.degrees(np.arctan2(r/A, c[2]/H)), np.ptp(X @ tm),
                     np.ptp(X @ et)))
    rows = np.array(rows)
    print("%d water faces on the cell; polar angle [deg]: count, mean "
          "extent along the meridian / the azimuth [um]" % len(F))
    for lo in range(0, 90, 10):
        s = (rows[:, 0] >= lo) & (rows[:, 0] < lo + 10)
        if s.sum():
            print("   %2d-%2d: %4d  %.2f / %.2f" % (
                lo, lo + 10, s.sum(), 1e6*rows[s, 1].mean(),
                1e6*rows[s, 2].mean()))


def main():
    a = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    a.add_argument("case")
    a.add_argument("--after", type=float, default=7.5e-8)
    a.add_argument("--fluid", nargs="+", default=None)
    a.add_argument("--vorticity", nargs="+", default=None)
    a.add_argument("--faces", action="store_true")
    a.add_argument("--zones", nargs="+", default=None)
    a.add_argument("--front", action="store_true")
    a.add_argument("--drive", nargs="+", default=None)
    o = a.parse_args()
    case = os.path.abspath(o.case)
    if o.fluid:
        return fluid(case, o.fluid)
    if o.vorticity:
        return vorticity(case, o.vorticity)
    if o.faces:
        return faces(case)
    if o.zones:
        return zoneFlow(case, o.zones)
    if o.front:
        return front(case)
    if o.drive:
        if len(o.drive) < 2:
            a.error("--drive: at least two times")
        return drive(case, o.drive)
    return solid(case, o.after)


if __name__ == "__main__":
    main()

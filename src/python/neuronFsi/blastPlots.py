"""The blast scene's plots and numbers (paper Fig. 10, Figs. 7-9 at 65.5 ns):
what tutorials/blast/plotBlast.py and the paper comparison
(applications/utilities/paperFigures) share.

    fig10(cases, labels, out)     probe 0 (cytoplasm-nucleus interface, 75 %
                                  of the nucleus height): pressure, von
                                  Mises, longitudinal strain and strain rate
                                  against time, with the plane-wave answer
    interfaceMaxima(case, out)    the interface measures: the largest
                                  mean over a fixed length of each
                                  interface (reported; the solver's
                                  interfacePatches.dat) over the element
                                  maxima (mesh-dependent)
    snapshot(case, out, time)     the solid at the write nearest time: r-z
                                  section (wedge) or a quarter cut away (3D)
    summary(case, until)          probe peaks, arrival, coupling statistics

Every reader error is a BlastPlotError naming the file.
"""
import os

import numpy as np
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

from . import script
from . import damageIndicators, logs, planeWave, postProcessing, resultDigest


class BlastPlotError(Exception):
    """A result that cannot be read; the message names the file."""


def series(case, log):
    """The rows of postProcessing/<dir>/<start>/<file> (log "dir/file")
    over every start of the run (a restart writes its rows under its start
    time), checked to reach the latest time the run wrote (a cut file,
    adv33 pb07)"""
    try:
        # as the run wrote it (its digests: adv53's p06b on the merge, an
        # edited probe log plotted and tabled by plotBlast.py)
        data = postProcessing.series(case, log, verify=True)
        postProcessing.checkCovers(case, log, data)
        return data
    except (postProcessing.ColumnFileError, resultDigest.DigestError) as err:
        raise BlastPlotError(str(err))


def interfaceNames(case):
    """the region interfaces of solidInterfaces/interfaceMaxima.dat"""
    return [n.split(":")[1] for n in postProcessing.names(
        case, "solidInterfaces/interfaceMaxima.dat") if n.startswith("pMax:")]


def probes(case):
    """time [s] and, for probe 0, p, vM, strainZ, strainRateZ"""
    d = series(case, "solidProbes/solidProbes.dat")
    nProbe = (d.shape[1] - 1)//7
    base = 1 + 5*nProbe
    return d[:, 0], d[:, 1], d[:, 2], d[:, base], d[:, base + 1]


def coupling(case):
    return series(case, "fsi/coupling.dat")


def wallTime(case):
    return logs.executionTime(f"{case}/log.cellBlastFoam")


def summary(case, until=np.inf):
    t, p, vm, ez, rate = probes(case)
    w = t <= until
    t, p, vm, ez, rate = t[w], p[w], vm[w], ez[w], rate[w]
    c = coupling(case)
    # arrival: p above half the applied pulse's amplitude (was 25 MPa, half
    # of the default 50 MPa, whatever Allrun -amplitude)
    try:
        half = 0.5*planeWave.pulseShape(planeWave.appliedPressure(case))[0]
    except planeWave.PlaneWaveError as err:
        raise BlastPlotError(str(err))
    arrival = t[np.argmax(p > half)] if np.any(p > half) else float("nan")
    cpu, clock = wallTime(case)
    return dict(
        pMax=p.max(), tpMax=t[np.argmax(p)], vmMax=vm.max(),
        tvmMax=t[np.argmax(vm)], strainMin=ez.min(), strainMax=ez.max(),
        rateMin=rate.min(), rateMax=rate.max(), arrival=arrival,
        steps=len(c), itMean=c[:, 2].mean(), itMax=int(c[:, 2].max()),
        notConverged=int(np.sum(c[:, 4] == 0)), cpu=cpu, clock=clock)


def planeWaveAnswer(case):
    """The exact answer at probe 0 (postProcessing/planeWave/0/
    reference.dat of the planeWave utility): time [s], p [Pa] of the 1D
    plane wave, and its uniaxial-strain von Mises [Pa] and strain [-] for
    probe 0's region (None, None for a reference without densities); or
    None"""
    path = os.path.join(case, "postProcessing", "planeWave", "0",
                        "reference.dat")
    solid = postProcessing.probes(case)
    if not os.path.isfile(path) or not solid:
        return None
    wave = planeWave.readReference(path)
    z = solid[0]["point"][1 if planeWave.isWedge(case) else 2]
    # at the probe's material point (a reference of planeWave since
    # g5ns); an older one has the probe's height only
    try:
        p, rho = wave.solidAt(z), wave.solidDensityAt(z)
    except planeWave.PlaneWaveError:
        try:
            p, rho = wave.at(z), wave.rho
            rho = None if rho is None else wave.densityAt(z)
        except planeWave.PlaneWaveError:
            return None
    vm = ez = None
    if rho is not None:
        rho0, mu0, branches = planeWave.solidMaterial(case,
                                                      solid[0]["region"])
        ez, vm = planeWave.uniaxialResponse(wave.t, rho, rho0, mu0,
                                            branches)
    return wave.t, p, vm, ez


def fig10(cases, labels, out, dpi=120, xlim=None):
    """Probe 0 of each case against time (pressure, von Mises,
    longitudinal strain and strain rate; paper Fig. 10), each with its
    plane-wave answer dashed in its colour; xlim: the time range shown
    [s] (default: the runs')."""
    fig, ax = plt.subplots(2, 2, figsize=(10, 7), sharex=True)
    for k, (case, lab) in enumerate(zip(cases, labels)):
        t, p, vm, ez, rate = probes(case)
        tn = t*1e9
        c = f"C{k}"
        ref = planeWaveAnswer(case)
        if ref is not None:
            ax[0, 0].plot(ref[0]*1e9, ref[1]/1e6, "--", color=c, lw=0.8,
                          label=f"{lab}: 1D plane wave (planeWave)")
            if ref[2] is not None:
                ax[0, 1].plot(ref[0]*1e9, ref[2], "--", color=c, lw=0.8,
                              label=f"{lab}: uniaxial strain (planeWave)")
                ax[1, 0].plot(ref[0]*1e9, ref[3], "--", color=c, lw=0.8)
        ax[0, 0].plot(tn, p/1e6, color=c, label=lab)
        ax[0, 1].plot(tn, vm, color=c, label=lab)
        ax[1, 0].plot(tn, ez, color=c, label=lab)
        ax[1, 1].plot(tn, rate, color=c, label=lab)
    ax[0, 0].set_ylabel("pressure [MPa]")
    ax[0, 1].set_ylabel("von Mises [Pa]")
    ax[1, 0].set_ylabel("longitudinal strain ln(stretch_z) [-]")
    ax[1, 1].set_ylabel("longitudinal strain rate [1/s]")
    for a in ax[1]:
        a.set_xlabel("time [ns]")
    for a in ax.flat:
        a.grid(alpha=0.3)
        if xlim is not None:
            a.set_xlim(xlim[0]*1e9, xlim[1]*1e9)
    ax[0, 0].legend(fontsize=8)
    ax[0, 1].legend(fontsize=8)
    fig.suptitle("Cytoplasm-nucleus interface, 75 % of the nucleus height "
                 "(paper Fig. 10)")
    fig.tight_layout()
    script.saveFigure(fig, out, dpi=dpi)
    plt.close(fig)


def interfacePatches(case):
    """The solver's interface means over a fixed length (the reported
    interface measure, damageIndicators.interfacePatches), None for a run
    that did not write them"""
    if not damageIndicators.hasInterfacePatches(case):
        return None
    try:
        postProcessing.checkCovers(case, damageIndicators.PATCH_LOG,
                                   postProcessing.series(
                                       case, damageIndicators.PATCH_LOG))
        return damageIndicators.interfacePatches(case)
    except postProcessing.ColumnFileError as err:
        raise BlastPlotError(str(err))


def interfaceMaxima(case, out, until=np.inf):
    """The interface measures against time: with interfacePatches.dat the
    reported means over a fixed length of interface (solid lines: von
    Mises and shear traction; membrane-fluid too) over the element maxima
    (thin dashed: mesh-dependent); without it the element maxima of
    pressure and von Mises of interfaceMaxima.dat. Returns {interface:
    (pMax, vmMax over t <= until, pMax, vmMax over the run)} of the
    element maxima and, with the patches, {interface + ' patch':
    (vonMisesPatch, shearPatch over t <= until, the same over the run)}."""
    d = series(case, "solidInterfaces/interfaceMaxima.dat")
    names = interfaceNames(case)
    ip = interfacePatches(case)
    fig, ax = plt.subplots(1, 2, figsize=(10, 4))
    if ip is None:
        for k, n in enumerate(names):
            ax[0].plot(d[:, 0]*1e9, d[:, 1 + 2*k]/1e6, label=n)
            ax[1].plot(d[:, 0]*1e9, d[:, 2 + 2*k], label=n)
        ax[0].set_ylabel("max pressure along the interface [MPa]")
        ax[1].set_ylabel("max von Mises along the interface [Pa]")
    else:
        L = damageIndicators.patchLength(case)
        for k, (n, v) in enumerate(ip.items()):
            t = v["t"]*1e9
            ax[0].plot(t, v["vonMisesPatch"], color=f"C{k}",
                       label=f"{n}: {L*1e6:g}-um mean")
            ax[0].plot(t, v["vonMisesMax"], color=f"C{k}", ls="--", lw=0.7,
                       label=f"{n}: element max")
            ax[1].plot(t, v["shearPatch"], color=f"C{k}",
                       label=f"{n}: {L*1e6:g}-um mean")
            ax[1].plot(t, v["shearMax"], color=f"C{k}", ls="--", lw=0.7,
                       label=f"{n}: element max")
        ax[0].set_ylabel("von Mises along the interface [Pa]")
        ax[1].set_ylabel("shear traction on the interface [Pa]")
        fig.suptitle(f"Interface measures: largest mean over {L*1e6:g} um "
                     "of interface (reported) and element maxima (dashed, "
                     "mesh-dependent)", fontsize=9)
    for a in ax:
        a.set_xlabel("time [ns]")
        a.grid(alpha=0.3)
        a.legend(fontsize=6)
    fig.tight_layout()
    script.saveFigure(fig, out, dpi=120)
    plt.close(fig)
    w = d[:, 0] <= until
    res = {n: (d[w, 1 + 2*k].max(), d[w, 2 + 2*k].max(),
               d[:, 1 + 2*k].max(), d[:, 2 + 2*k].max())
           for k, n in enumerate(names)}
    if ip is not None:
        for n, v in ip.items():
            w = v["t"] <= until
            res[n + " patch"] = (v["vonMisesPatch"][w].max(),
                                 v["shearPatch"][w].max(),
                                 v["vonMisesPatch"].max(),
                                 v["shearPatch"].max())
    return res


def interfaceMaximaCases(cases, labels, out):
    """Interface measures of several runs: colour per case, style per
    interface; the patch means (reported) where the runs wrote them, else
    the element maxima"""
    fig, ax = plt.subplots(1, 2, figsize=(11, 4.5))
    styles = ["-", "--", ":", "-."]
    patches = all(damageIndicators.hasInterfacePatches(c) for c in cases)
    for c, (case, lab) in enumerate(zip(cases, labels)):
        if patches:
            for k, (n, v) in enumerate(interfacePatches(case).items()):
                kw = dict(color=f"C{c}", ls=styles[k % 4], label=f"{lab} {n}")
                ax[0].plot(v["t"]*1e9, v["vonMisesPatch"], **kw)
                ax[1].plot(v["t"]*1e9, v["shearPatch"], **kw)
            continue
        d = series(case, "solidInterfaces/interfaceMaxima.dat")
        names = interfaceNames(case)
        for k, n in enumerate(names):
            kw = dict(color=f"C{c}", ls=styles[k % 4], label=f"{lab} {n}")
            ax[0].plot(d[:, 0]*1e9, d[:, 1 + 2*k]/1e6, **kw)
            ax[1].plot(d[:, 0]*1e9, d[:, 2 + 2*k], **kw)
    if patches:
        L = damageIndicators.patchLength(cases[0])
        ax[0].set_ylabel(f"von Mises, largest {L*1e6:g}-um mean [Pa]")
        ax[1].set_ylabel(f"shear traction, largest {L*1e6:g}-um mean [Pa]")
        fig.suptitle("Region-interface measures: the largest mean over a "
                     "fixed length of interface")
    else:
        ax[0].set_ylabel("max pressure along the interface [MPa]")
        ax[1].set_ylabel("max von Mises along the interface [Pa]")
        fig.suptitle("Region-interface maxima (membrane-cytoplasm, "
                     "cytoplasm-nucleus)")
    for a in ax:
        a.set_xlabel("time [ns]")
        a.grid(alpha=0.3)
    ax[1].legend(fontsize=7)
    fig.tight_layout()
    script.saveFigure(fig, out, dpi=120)
    plt.close(fig)


# hex8 faces (gmsh/VTK node order), outward
HEX_FACES = ((0, 3, 2, 1), (4, 5, 6, 7), (0, 1, 5, 4), (1, 2, 6, 5),
             (2, 3, 7, 6), (3, 0, 4, 7))


def snapshot3D(tk, X, conn, p, vm, out, dT=None, dpi=120):
    """The 3D cell at one time with a quarter cut away (paper Figs. 7-8):
    the solid's element pressure and von Mises on its outer surface and
    on the two cut planes x = 0 and y = 0. A quarter case (x, y >= 0,
    symmetry planes) is mirrored into the other three quarters and its own
    quarter is the one cut away, so that the cut faces are its symmetry
    faces; a whole cell shows the elements outside x, y > 0."""
    from mpl_toolkits.mplot3d.art3d import Poly3DCollection
    L = np.ptp(X, axis=0).max()
    tol = 1e-6*L
    quarter = X[:, 0].min() > -tol and X[:, 1].min() > -tol
    cent = X[conn].mean(axis=1)
    keep = np.ones(len(conn), bool) if quarter else \
        ~((cent[:, 0] > 0) & (cent[:, 1] > 0))
    owner = {}          # face (sorted nodes) -> [elements sharing it, one]
    for e in np.nonzero(keep)[0]:
        for fn in HEX_FACES:
            o = owner.setdefault(tuple(sorted(conn[e, list(fn)])), [0, e, fn])
            o[0] += 1
    faces = {"outer": [], "x0": [], "y0": []}
    for n, e, fn in owner.values():
        if n != 1:
            continue                        # shared by two: inside
        q = X[conn[e, list(fn)]]
        if np.all(np.abs(q[:, 2]) < tol):
            continue                        # on the substrate: not seen
        if np.all(np.abs(q[:, 0]) < tol):
            faces["x0"].append((q, e))
        elif np.all(np.abs(q[:, 1]) < tol):
            faces["y0"].append((q, e))
        else:
            faces["outer"].append((q, e))
    polys, elems = [], []
    if quarter:
        # outer surface of the three mirrored quarters; the cut faces are
        # the quarter's own symmetry faces (x = 0 for y > 0 belongs to the
        # (-x, y) copy, y = 0 for x > 0 to the (x, -y) copy: the same
        # points)
        for sx, sy in ((-1, 1), (1, -1), (-1, -1)):
            for q, e in faces["outer"]:
                polys.append(q*np.array([sx, sy, 1]))
                elems.append(e)
        for q, e in faces["x0"] + faces["y0"]:
            polys.append(q)
            elems.append(e)
    else:
        # the whole cell: faces exposed by the cut lie on x = 0 (y > 0) or
        # y = 0 (x > 0); boundary faces of the kept set on the other halves
        # of those planes do not exist (their neighbours are kept)
        for q, e in faces["outer"] + faces["x0"] + faces["y0"]:
            polys.append(q)
            elems.append(e)
    polys = np.array(polys)*1e6
    elems = np.array(elems)
    panels = [(p/1e6, "pressure [MPa]", "viridis"),
              (vm, "von Mises [Pa]", "magma")]
    if dT is not None:
        panels.append((dT, "temperature rise [K] (Fig. 9)", "inferno"))
    fig = plt.figure(figsize=(6.5*len(panels), 6.4))
    R = np.abs(X[:, :2]).max()*1e6
    H = X[:, 2].max()*1e6
    for k, (v, lab, cmap) in enumerate(panels):
        a = fig.add_subplot(1, len(panels), k + 1, projection="3d")
        pc = Poly3DCollection(polys, array=v[elems], cmap=cmap,
                              edgecolors="k", linewidths=0.05)
        a.add_collection3d(pc)
        a.set_xlim(-R, R)
        a.set_ylim(-R, R)
        a.set_zlim(0, H)
        a.set_box_aspect((2*R, 2*R, H))
        a.view_init(elev=28, azim=40)
        a.set_xlabel("x [um]")
        a.set_ylabel("y [um]")
        a.set_zlabel("z [um]")
        fig.colorbar(pc, ax=a, label=lab, shrink=0.6, pad=0.02,
                     orientation="horizontal")
    fig.suptitle(f"Solid at t = {tk*1e9:.2f} ns, a quarter cut away (cut "
                 "planes x = 0 and y = 0 through nucleus, cytoplasm and the "
                 "200 nm membrane)" + ("; the computed quarter mirrored "
                                       "about them" if quarter else ""),
                 fontsize=10)
    fig.tight_layout()
    script.saveFigure(fig, out, dpi=dpi)
    plt.close(fig)
    return tk


def snapshot(case, out, time=65.5e-9, temperature=False, dpi=120):
    """The solid at the write of solid/solid.h5 nearest time [s]: pressure,
    von Mises and temperature rise on the r-z section mirrored about the
    axis (a wedge case), or pressure and von Mises (and the temperature
    rise with temperature) on the 3D cell with a quarter cut away; the
    time of that write [s]."""
    from matplotlib.collections import PolyCollection
    from neuronFsi.solidResults import SolidResults
    with SolidResults(f"{case}/solid/solid.h5") as f:
        k = f.nearest(time)
        tk = f.time(k)
        conn = f.mesh("connectivity")
        p = f.field(k, "pressure")
        vm = f.field(k, "vonMises")
        # the adiabatic temperature rise (paper Fig. 9, eqs. 7-8; regions
        # with the Mie-Grueneisen law only: the membrane's quadratic law
        # has no energy equation, 0 there)
        dT = f.field(k, "temperatureRise")
        X = f.mesh("coordinates") + f.field(k, "displacement")
    if conn.shape[1] == 8:
        return snapshot3D(tk, X, conn, p, vm, out,
                          dT if temperature else None, dpi)
    X = X[:, :2]
    polys = X[conn]*1e6
    mirror = polys*np.array([-1, 1])
    fig, ax = plt.subplots(1, 3, figsize=(17, 4))
    for a, v, lab, cmap in ((ax[0], p/1e6, "pressure [MPa]", "viridis"),
                            (ax[1], vm, "von Mises [Pa]", "magma"),
                            (ax[2], dT, "temperature rise [K] (Fig. 9)",
                             "inferno")):
        pc = PolyCollection(np.concatenate([polys, mirror]), array=np.r_[v, v],
                            cmap=cmap, edgecolors="face", linewidths=0.2)
        a.add_collection(pc)
        a.set_xlim(-9, 9)
        a.set_ylim(-0.3, 8.3)
        a.set_aspect("equal")
        a.set_xlabel("r [um]")
        a.set_ylabel("z [um]")
        fig.colorbar(pc, ax=a, label=lab, shrink=0.8)
    fig.suptitle(f"Solid at t = {tk*1e9:.2f} ns (r-z section mirrored about "
                 "the axis; nucleus, cytoplasm and 200 nm membrane)")
    fig.tight_layout()
    script.saveFigure(fig, out, dpi=dpi)
    plt.close(fig)
    return tk


def row(lab, s):
    return (f"{lab:>14s} {s['arrival']*1e9:8.2f} {s['pMax']/1e6:8.2f} "
            f"{s['tpMax']*1e9:7.2f} {s['vmMax']:9.3f} {s['strainMin']:10.3e} "
            f"{s['rateMin']:10.3e} {s['rateMax']:10.3e} {s['steps']:6d} "
            f"{s['itMean']:5.2f} {s['itMax']:3d} {s['notConverged']:3d} "
            f"{s['cpu']:8.1f} {s['clock']:8.1f}")


header = (f"{'case':>14s} {'arr[ns]':>8s} {'pMax[MPa]':>8s} {'t[ns]':>7s} "
          f"{'vMmax[Pa]':>9s} {'strainMin':>10s} {'rateMin[1/s]':>10s} "
          f"{'rateMax[1/s]':>10s} {'steps':>6s} {'itAv':>5s} {'itM':>3s} "
          f"{'nc':>3s} {'cpu[s]':>8s} {'clock[s]':>8s}")

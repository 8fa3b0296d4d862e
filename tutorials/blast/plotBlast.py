#!/usr/bin/python3
"""Blast scene plots and numbers (paper Fig. 10, Figs. 7-8 at 65.5 ns).

usage: plotBlast.py case [case ...] [-o prefix] [-label name ...]
                    [-until 1.5e-7]
Probe peaks are taken over t <= until (default: the whole run), the
interface maxima both over the window and over the run.

One case: <case>/fig10.png (pressure, von Mises, longitudinal strain and
strain rate at the probe on the cytoplasm-nucleus interface at 75 % of the
nucleus height), <case>/interfaceMaxima.png, <case>/snapshot65.5ns.png
(solid pressure and von Mises on the r-z section, mirrored about the axis,
at the write time nearest 65.5 ns) and <case>/postProcessing/
blastSummary.dat (probe peaks, arrival time, coupling statistics).
Several cases (pulse or mesh study): the Fig. 10 curves on one figure
<prefix>fig10.png, the interface maxima against time of every case on
<prefix>interfaceMaxima.png and a summary table on stdout.
"""
import glob
import sys
import os
import numpy as np
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

args = sys.argv[1:]
prefix, labels, cases, until = None, [], [], np.inf
i = 0
while i < len(args):
    if args[i] == "-o":
        prefix = args[i + 1]; i += 2
    elif args[i] == "-until":
        until = float(args[i + 1]); i += 2
    elif args[i] == "-label":
        labels.append(args[i + 1]); i += 2
    else:
        cases.append(args[i]); i += 1
if not cases:
    sys.exit(__doc__)
labels += [os.path.basename(os.path.abspath(c)) for c in cases[len(labels):]]


def load(f):
    """Rows of a column file (a last line still being written is skipped)"""
    rows = [line.split() for line in open(f) if not line.startswith("#")]
    n = len(rows[0])
    return np.array([r for r in rows if len(r) == n], dtype=float)


def series(case, log):
    """The rows of postProcessing/<dir>/<start>/<file> (log "dir/file")
    over every start of the run (a restart writes its rows under its start
    time): each start's rows up to the next start, earliest first"""
    d, name = log.split("/")
    segs = sorted((float(os.path.basename(os.path.dirname(p))), p) for p in
                  glob.glob(f"{case}/postProcessing/{d}/*/{name}"))
    if not segs:
        sys.exit(f"plotBlast.py: no {case}/postProcessing/{d}/*/{name}")
    parts = []
    for k, (t0, p) in enumerate(segs):
        a = load(p)
        if k + 1 < len(segs):
            a = a[a[:, 0] <= segs[k + 1][0]*(1 + 1e-12)]
        parts.append(a)
    return np.vstack(parts)


def logHeader(case, log):
    """the header lines of the run's first start of a log"""
    d, name = log.split("/")
    first = min(glob.glob(f"{case}/postProcessing/{d}/*/{name}"),
                key=lambda p: float(os.path.basename(os.path.dirname(p))))
    return [line for line in open(first) if line.startswith("#")]


def probes(case):
    """time [s] and, for probe 0, p, vM, strainZ, strainRateZ"""
    d = series(case, "solidProbes/solidProbes.dat")
    nProbe = (d.shape[1] - 1)//7
    base = 1 + 5*nProbe
    return d[:, 0], d[:, 1], d[:, 2], d[:, base], d[:, base + 1]


def coupling(case):
    return series(case, "fsi/coupling.dat")


def wallTime(case):
    for line in reversed(open(f"{case}/log.cellBlastFoam").readlines()):
        if line.startswith("ExecutionTime"):
            w = line.split()
            return float(w[2]), float(w[6])
    return float("nan"), float("nan")


def summary(case):
    t, p, vm, ez, rate = probes(case)
    w = t <= until
    t, p, vm, ez, rate = t[w], p[w], vm[w], ez[w], rate[w]
    c = coupling(case)
    arrival = t[np.argmax(p > 25e6)] if np.any(p > 25e6) else float("nan")
    cpu, clock = wallTime(case)
    return dict(
        pMax=p.max(), tpMax=t[np.argmax(p)], vmMax=vm.max(),
        tvmMax=t[np.argmax(vm)], strainMin=ez.min(), strainMax=ez.max(),
        rateMin=rate.min(), rateMax=rate.max(), arrival=arrival,
        steps=len(c), itMean=c[:, 2].mean(), itMax=int(c[:, 2].max()),
        notConverged=int(np.sum(c[:, 4] == 0)), cpu=cpu, clock=clock)


def fig10(cases, labels, out):
    fig, ax = plt.subplots(2, 2, figsize=(10, 7), sharex=True)
    for case, lab in zip(cases, labels):
        t, p, vm, ez, rate = probes(case)
        tn = t*1e9
        ax[0, 0].plot(tn, p/1e6, label=lab)
        ax[0, 1].plot(tn, vm, label=lab)
        ax[1, 0].plot(tn, ez, label=lab)
        ax[1, 1].plot(tn, rate, label=lab)
    ax[0, 0].set_ylabel("pressure [MPa]")
    ax[0, 1].set_ylabel("von Mises [Pa]")
    ax[1, 0].set_ylabel("longitudinal strain ln(stretch_z) [-]")
    ax[1, 1].set_ylabel("longitudinal strain rate [1/s]")
    for a in ax[1]:
        a.set_xlabel("time [ns]")
    for a in ax.flat:
        a.grid(alpha=0.3)
    ax[0, 0].legend()
    fig.suptitle("Cytoplasm-nucleus interface, 75 % of the nucleus height "
                 "(paper Fig. 10)")
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    plt.close(fig)


def interfaceMaxima(case, out):
    d = series(case, "solidInterfaces/interfaceMaxima.dat")
    names = [w.split(":")[1].split("[")[0] for w in
             logHeader(case, "solidInterfaces/interfaceMaxima.dat")[1]
             .split()[2:] if w.startswith("pMax")]
    fig, ax = plt.subplots(1, 2, figsize=(10, 4))
    for k, n in enumerate(names):
        ax[0].plot(d[:, 0]*1e9, d[:, 1 + 2*k]/1e6, label=n)
        ax[1].plot(d[:, 0]*1e9, d[:, 2 + 2*k], label=n)
    ax[0].set_ylabel("max pressure along the interface [MPa]")
    ax[1].set_ylabel("max von Mises along the interface [Pa]")
    for a in ax:
        a.set_xlabel("time [ns]")
        a.grid(alpha=0.3)
        a.legend()
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    plt.close(fig)
    w = d[:, 0] <= until
    return {n: (d[w, 1 + 2*k].max(), d[w, 2 + 2*k].max(),
                d[:, 1 + 2*k].max(), d[:, 2 + 2*k].max())
            for k, n in enumerate(names)}


def interfaceMaximaCases(cases, labels, out):
    """Interface maxima of several runs: colour per case, style per
    interface"""
    fig, ax = plt.subplots(1, 2, figsize=(11, 4.5))
    styles = ["-", "--", ":", "-."]
    for c, (case, lab) in enumerate(zip(cases, labels)):
        d = series(case, "solidInterfaces/interfaceMaxima.dat")
        names = [w.split(":")[1].split("[")[0] for w in
                 logHeader(case, "solidInterfaces/interfaceMaxima.dat")[1]
                 .split()[2:] if w.startswith("pMax")]
        for k, n in enumerate(names):
            kw = dict(color=f"C{c}", ls=styles[k % 4], label=f"{lab} {n}")
            ax[0].plot(d[:, 0]*1e9, d[:, 1 + 2*k]/1e6, **kw)
            ax[1].plot(d[:, 0]*1e9, d[:, 2 + 2*k], **kw)
    ax[0].set_ylabel("max pressure along the interface [MPa]")
    ax[1].set_ylabel("max von Mises along the interface [Pa]")
    for a in ax:
        a.set_xlabel("time [ns]")
        a.grid(alpha=0.3)
    ax[1].legend(fontsize=7)
    fig.suptitle("Region-interface maxima (membrane-cytoplasm, "
                 "cytoplasm-nucleus)")
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    plt.close(fig)


def snapshot(case, out, time=65.5e-9):
    import h5py
    from matplotlib.collections import PolyCollection
    with h5py.File(f"{case}/solid/solid.h5", "r") as f:
        steps = f["steps"]
        k = min(steps, key=lambda s: abs(steps[s].attrs["time"] - time))
        tk = steps[k].attrs["time"]
        X = f["mesh/coordinates"][:, :2] + steps[k]["displacement"][:, :2]
        conn = f["mesh/connectivity"][:]
        p = steps[k]["pressure"][:]
        vm = steps[k]["vonMises"][:]
    polys = X[conn]*1e6
    mirror = polys*np.array([-1, 1])
    fig, ax = plt.subplots(1, 2, figsize=(12, 4))
    for a, v, lab, cmap in ((ax[0], p/1e6, "pressure [MPa]", "viridis"),
                            (ax[1], vm, "von Mises [Pa]", "magma")):
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
    fig.savefig(out, dpi=120)
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

if len(cases) == 1:
    case = cases[0]
    fig10(cases, labels, f"{case}/fig10.png")
    im = interfaceMaxima(case, f"{case}/interfaceMaxima.png")
    tk = snapshot(case, f"{case}/snapshot65.5ns.png")
    s = summary(case)
    lines = ["# probe 0 (cytoplasm-nucleus interface, 75 % nucleus height)",
             f"# peaks over t <= {until*1e9:g} ns; arrival: first p > 25 MPa;"
             " coupling and times: whole run", header, row(labels[0], s)]
    for n, (pm, vmm, pa, vma) in im.items():
        lines.append(f"# interface {n}: max pressure {pm/1e6:.3f} MPa, "
                     f"max von Mises {vmm:.3f} Pa (t <= {until*1e9:g} ns); "
                     f"whole run {pa/1e6:.3f} MPa, {vma:.3f} Pa")
    lines.append(f"# snapshot at {tk*1e9:.3f} ns")
    open(f"{case}/postProcessing/blastSummary.dat", "w").write(
        "\n".join(lines) + "\n")
    print("\n".join(lines))
else:
    fig10(cases, labels, f"{prefix or ''}fig10.png")
    interfaceMaximaCases(cases, labels, f"{prefix or ''}interfaceMaxima.png")
    print(f"# probe peaks over t <= {until*1e9:g} ns")
    print(header)
    for case, lab in zip(cases, labels):
        print(row(lab, summary(case)))

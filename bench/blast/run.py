#!/usr/bin/python3
"""Blast preview per mesh: cost against error (not a test).

Runs tutorials/blast/axisymmetricPreview (the average cell on the substrate
under a 100 um water column, 50 MPa for 5 ns on the top face) on a mesh
ladder: the fluid size at the cell (-h 0.25e-6 m), the far column size
(-far 1e-6 m across, -dz 0.25e-6 m along) and the solid size (-cell 0.5e-6 m; membrane 0.8 of it) are
scaled together by each factor, so that every level keeps the default's
ratio of fluid face to membrane face (0.25/0.4; level x0.7 is the
tutorial's default since 2026-12-04; the Allrun header: fluid
faces at the cell about half the solid face size, never as large as them,
docs/results/blast.md, known failure). Each level runs in a scratch copy of
the tutorial (./Allrun -noRun -noPlots with the sizes, then cellBlastFoam
under /usr/bin/time -v), one after the other (one core).

Per level: fluid cells, solid elements, time steps, mean coupling passes
per step, unconverged steps, CPU and wall time of cellBlastFoam (its own
ExecutionTime/ClockTime, to the Fig. 10 window end and to the end time),
peak resident memory, and the Fig. 10 probe (cytoplasm-nucleus interface,
75 % of the nucleus height): peak pressure, peak von Mises, peak (most
negative) longitudinal strain ln(stretch_z) and strain rate over the window,
arrival time (first p > 25 MPa); then each difference to the finest level.

    bench/blast/run.py [--quick] [--out DIR] [--doc FILE]
                    [--factors "1.4 1 0.7"] [--endTime s]
                    [--allrun "-shearViscosity 0.1 -shearViscosityFilter no"]

Full: factors 1.4 1 0.7, 100 um column to 150 ns, probe peaks over
t <= 90 ns (the first passage: the Fig. 10 numbers to quote), about
25-35 min of CPU on one core. --quick: the same factors on a 20 um column
to 25 ns (about 2-3 min), written into --out (default bench/blast/output).
Writes docs/benchmarks/blast.md and blast_cost_vs_error.png (full) or
<out>/blast.md and its PNG (quick).
"""
import datetime
import math
import os
import sys

import numpy as np

try:
    from neuronFsi import script
except ImportError:
    sys.exit("bench/blast/run.py: error: the project's Python package neuronFsi "
             "is not found: source the project's etc/bashrc first")
script.guard()  # an input's error: one line, exit 1 (adv33)
from neuronFsi import bench, convergence, logs, msh, planeWave, \
    postProcessing, scratch

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", ".."))
TUTORIAL = os.path.join(ROOT, "tutorials", "blast")
# [m] level x1: the tutorial's default sizes until 2026-12-04; the default
# since then is level x0.7 (the commands quoted in docs/ keep their levels)
DEFAULT = dict(h=0.25e-6, far=1e-6, dz=0.25e-6, cell=0.5e-6)
PULSE = 5e-9                                        # [s]
SIZES = {
    "full": dict(factors=["1.4", "1", "0.7"], Z=100e-6, endTime=1.5e-7,
                 window=9e-8),
    "quick": dict(factors=["1.4", "1", "0.7"], Z=20e-6, endTime=2.5e-8,
                  window=2.5e-8),
}
ARRIVAL = 25e6          # [Pa] arrival: first probe pressure above it
SOURCES, SOURCES_TEXT = bench.measuredCode("blast")


def prepare(case, f, Z, endTime, env, extra=(), pulse=PULSE):
    """Scratch copy of the tutorial (inputs only, as tests/blast/
    runPreview.sh) in case/, meshes and fields prepared by Allrun -noRun
    (sizes scaled by f; extra: more Allrun options)"""
    # an earlier case of this script only, never a user's folder (adv51
    # n01 (j))
    scratch.outputFolder("run.py", case, ("@case",))
    scratch.copyInputs(TUTORIAL, case,
                       ("fluidWedgeMesh.py", "plotBlast.py"))
    c = os.path.join(case, "axisymmetricPreview")
    scratch.copyInputs(os.path.join(TUTORIAL, "axisymmetricPreview"), c,
                     ("0.orig", "constant", "system", "Allrun", "Allclean"),
                     ("cell.msh", "polyMesh", "blockMeshDict"))
    x = float(f)
    sizes = {k: v*x for k, v in DEFAULT.items()}
    cmd = ["./Allrun", "-noRun", "-noPlots", "-pulse", f"{pulse:g}",
           "-h", f"{sizes['h']:.6g}", "-far", f"{sizes['far']:.6g}",
           "-dz", f"{sizes['dz']:.6g}", "-cell", f"{sizes['cell']:.6g}",
           "-Z", f"{Z:g}",
           "-endTime", f"{endTime:g}"] + list(extra)
    res = bench.runLogged(cmd, c, env, "log.Allrun")
    if res.returncode != 0:
        bench.fail(res, f"Allrun -noRun failed in {c}")
    return c, sizes, " ".join(cmd)


def timeV(path):
    """/usr/bin/time -v: max RSS [MB], user + system [s], wall [s]"""
    r = logs.timeV(path)
    return r["rss"]/1024, r["user"] + r["system"], r["wall"], r["status"]


def logTimes(log, window):
    """cellBlastFoam's ExecutionTime/ClockTime [s] at the end of the run
    and at the first step with t >= window (the last step if the run
    ends within 0.1 ns of it); the last time reached [s];
    its CPU split line"""
    last = logs.executionTime(log)
    atWindow = next(((cpu, clock) for t, cpu, clock in logs.timeSteps(log)
                     if t >= window), None)
    t = logs.lastTime(log)
    # OpenFOAM ends a run up to half a step short of endTime: a window at
    # the end time is reached within 0.1 ns
    if atWindow is None and t is not None and t >= window - 1e-10:
        atWindow = last
    return last, atWindow, t, logs.cpuSplit(log)


def count(c):
    """fluid cells (checkMesh) and solid elements (the quads of the cell's
    MSH file)"""
    return (logs.checkMeshCells(os.path.join(c, "log.checkMesh")),
            msh.elementCount(os.path.join(c, "constant", "cell.msh"), {3}))


def runLevel(f, out, size, env):
    """prepare and run one level; its results are in files of the case
    (parseLevel reads them)"""
    c, sizes, cmd = prepare(os.path.join(out, f"level_{f}"), f,
                            size["Z"], size["endTime"], env,
                            size.get("extra", ()))
    cells, elements = count(c)
    print(f"factor {f}: {cells} fluid cells, {elements} solid elements "
          f"(h {sizes['h']:.3g} m, far {sizes['far']:.3g} m, cell "
          f"{sizes['cell']:.3g} m); running cellBlastFoam ...", flush=True)
    bench.runTimed(c, ["cellBlastFoam"], env, "log.cellBlastFoam")
    return parseLevel(f, out, size)


def parseLevel(f, out, size, name=None):
    """the results of a level run in out/level_f (or out/name:
    cellBlastFoam's logs, /usr/bin/time, postProcessing)"""
    window = size["window"]
    c = os.path.join(out, name or f"level_{f}", "axisymmetricPreview")
    x = float(f)
    sizes = {k: v*x for k, v in DEFAULT.items()}
    cmd = ("./Allrun -noRun -noPlots -pulse " f"{PULSE:g} -h "
           f"{sizes['h']:.6g} -far {sizes['far']:.6g} -dz "
           f"{sizes['dz']:.6g} -cell "
           f"{sizes['cell']:.6g} -Z {size['Z']:g} -endTime "
           f"{size['endTime']:g}")
    cells, elements = count(c)
    rss, cpuTimeV, wallTimeV, rc = timeV(os.path.join(c, "log.time"))
    if rc is None:      # killed by a signal: /usr/bin/time says so
        rc = -1 if "Command terminated by signal" in open(
            os.path.join(c, "log.time")).read() else 0
    (cpu, wall), atWindow, tLast, split = logTimes(
        os.path.join(c, "log.cellBlastFoam"), window)
    r = dict(factor=f, sizes=sizes, cells=cells, elements=elements,
             cmd=cmd, case=c, rc=rc,
             tLast=tLast, rss=rss, cpuTimeV=cpuTimeV, wallTimeV=wallTimeV,
             cpu=cpu, wall=wall, atWindow=atWindow, split=split,
             load=bench.loadAverage(c))
    if rc != 0:
        log = os.path.join(c, "log.cellBlastFoam")
        tail = logs.text(log)[-4000:]
        m = logs.fatalErrors(log)
        r["error"] = (m[-1] if m else tail[-1500:]).strip()
        print(f"factor {f}: cellBlastFoam FAILED (exit {rc}) "
              f"at t = {tLast} s:\n{r['error']}", flush=True)
    r.update(bench.couplingStatistics(c))
    pf = "solidProbes/solidProbes.dat"
    # the probe point, the element containing it and the recovery patch
    for probe in postProcessing.probes(c, pf)[:1]:
        r.update(probePoint=probe["point"][:2],
                 probeElement=probe["element"],
                 probeRegion=probe["region"], probePatch=probe["patch"])
    p = postProcessing.series(c, pf)
    nProbe = (p.shape[1] - 1)//7
    base = 1 + 5*nProbe
    t, pr, vm, ez, rate = p[:, 0], p[:, 1], p[:, 2], p[:, base], \
        p[:, base + 1]
    r["series"] = (t, pr)
    w = t <= window*(1 + 1e-9)
    r.update(pMax=pr[w].max(), tpMax=t[w][np.argmax(pr[w])],
             vmMax=vm[w].max(), strainMin=ez[w].min(),
             rateMin=rate[w].min(),
             arrival=t[np.argmax(pr > ARRIVAL)] if np.any(pr > ARRIVAL)
             else float("nan"))
    # the strain rate averaged over RATE_WINDOW (centred): the change of
    # the strain over the window, which converges where the raw peak
    # across the shock does not
    tc, rate1 = planeWave.runningMean(t, rate, RATE_WINDOW)
    r["rate1nsMin"] = rate1[tc <= window*(1 + 1e-9)].min()
    # the region interfaces' von Mises maxima over the window
    im = postProcessing.series(c, "solidInterfaces/interfaceMaxima.dat")
    wi = im[:, 0] <= window*(1 + 1e-9)
    r.update(vmMC=im[wi, 2].max(), vmCN=im[wi, 4].max())
    # at rest after the pulse: the largest |strain_z| and von Mises from
    # REST on (issue 17 item 6: below 1e-3 and 10 % of the pulse peak)
    late = t >= REST
    r["rest"] = ((np.abs(ez[late]).max(), vm[late].max()) if t[-1] >=
                 REST + 5e-9 else None)
    cw = (f"{atWindow[0]:.1f} s to {window*1e9:.0f} ns, " if atWindow
          else "")
    print(f"factor {f}: {r['steps']} steps, {r['itMean']:.2f} passes/step, "
          f"{r['notConverged']} unconverged; CPU {cw}{cpu:.1f} s to "
          f"{tLast*1e9:.1f} ns, wall {wall:.1f} s, peak RSS {rss:.0f} MB; "
          f"probe peak p {r['pMax']/1e6:.2f} MPa, vM {r['vmMax']:.3f} Pa, "
          f"strain {r['strainMin']:.4f}, rate {r['rateMin']:.3e} 1/s, "
          f"arrival {r['arrival']*1e9:.2f} ns", flush=True)
    return r


QUANTITIES = [("pMax", "peak p"), ("vmMax", "peak von Mises"),
              ("strainMin", "peak strain"), ("rateMin", "peak strain rate"),
              ("rate1nsMin", "peak 1-ns strain rate"),
              ("vmMC", "interface vM max m-c"),
              ("vmCN", "interface vM max c-n")]
# the quantities that should converge (the raw peak strain rate across a
# captured shock grows as 1/dx: it has no mesh limit)
CONVERGING = [k for k, _ in QUANTITIES if k != "rateMin"]
RATE_WINDOW = 1e-9      # [s] window of the averaged strain rate
REST = 1.4e-7           # [s] "after the pulse" (issue 17 item 6) from here


def diffs(r, ref):
    """relative differences to ref [%] of the four probe peaks, arrival
    difference [ns]"""
    d = {k: 100*(r[k]/ref[k] - 1) for k, _ in QUANTITIES}
    d["arrival"] = (r["arrival"] - ref["arrival"])*1e9
    d["max"] = max(abs(d[k]) for k, _ in QUANTITIES)
    return d


def plot(rows, ref, size, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(1, 2, figsize=(12, 4.6))
    others = [r for r in rows if r is not ref and r["rc"] == 0]
    marks = ["o-", "s--", "^-.", "v:", "<-", ">--", "d-."]
    for (k, lab), m in zip(QUANTITIES, marks):
        x = [r["cpu"] for r in others]
        y = [max(abs(diffs(r, ref)[k]), 1e-3) for r in others]
        ax[0].loglog(x, y, m, label=lab)
    for r in others:
        ax[0].annotate(f"x{r['factor']}: {r['cells']} cells, "
                       f"{r['elements']} el.",
                       (r["cpu"], max(diffs(r, ref)["max"], 1e-3)),
                       fontsize=7, xytext=(4, 4), textcoords="offset points")
    ax[0].set_xlabel(f"CPU time of cellBlastFoam to "
                     f"{size['endTime']*1e9:.0f} ns [s]")
    ax[0].set_ylabel(f"|value/finest - 1| [%] (finest: x{ref['factor']}, "
                     f"{ref['cells']} cells)")
    ax[0].set_title(f"Fig. 10 probe peaks (t <= {size['window']*1e9:.0f} ns)"
                    " against cost", fontsize=10)
    ax[0].grid(True, which="both", alpha=0.3)
    ax[0].legend(fontsize=8)
    for r in rows:
        t, p = r["series"]
        ax[1].plot(t*1e9, p/1e6, label=f"x{r['factor']}: {r['cells']} cells,"
                   f" {r['elements']} el." + ("" if r["rc"] == 0
                                              else " (FAILED)"))
    ax[1].set_xlabel("time [ns]")
    ax[1].set_ylabel("probe pressure [MPa]")
    ax[1].set_title("Probe pressure (cytoplasm-nucleus interface, 75 % "
                    "nucleus height)", fontsize=9)
    a = [r["arrival"] for r in rows if not math.isnan(r["arrival"])]
    if a:
        ax[1].set_xlim(max(0, min(a)*1e9 - 5),
                       min(size["endTime"], min(a) + 3e-8)*1e9)
    ax[1].grid(alpha=0.3)
    ax[1].legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


def choose(rows, ref, key="max"):
    """the cheapest level whose peak difference (key: one quantity or the
    largest of the four) is below each threshold [%]"""
    out = []
    ok = sorted([r for r in rows if r["rc"] == 0 and r is not ref],
                key=lambda r: r["cpu"])
    for e in (1, 2, 5, 10, 20):
        best = next((r for r in ok if abs(diffs(r, ref)[key]) <= e), None)
        out.append((e, best))
    return out


def successive(good):
    """per quantity: the changes between consecutive levels [%] of the
    finer one, and the observed order of the three finest levels where
    the changes shrink without changing sign (richardson's)"""
    out = []
    for k, lab in QUANTITIES:
        ch = [100*(b[k]/a[k] - 1) for a, b in zip(good, good[1:])]
        R = richardson(good, k)
        out.append((lab, ch, R.p if R else None))
    return out


def richardson(levels, key):
    """neuronFsi.convergence.threeLevel of the quantity key over the levels
    (h = their size factor); None where it has no verdict (fewer than three
    levels, a value not finite)"""
    try:
        return convergence.threeLevel([float(r["factor"]) for r in levels],
                                      [r[key] for r in levels])
    except ValueError:
        return None


def report(rows, size, mode, start, png, commit, dirty, end,
           reportOnly=False):
    good = [r for r in rows if r["rc"] == 0]
    ref = min(good, key=lambda r: float(r["factor"]))
    win = size["window"]*1e9
    endNs = size["endTime"]*1e9
    L = []
    w = L.append
    w("# Blast preview per mesh: cost against error")
    w("")
    w(bench.levelsWrittenBy("bench/blast/run.py", mode, start, end, commit,
                            dirty, SOURCES_TEXT, reportOnly) + ". "
      f"Machine: {os.cpu_count()} cores shared with other engineers' builds "
      "and runs (load average at the end of each level in the table), so "
      "wall times are noisy: the CPU time of cellBlastFoam is the one-core "
      "cost to compare.")
    w("")
    w(f"Case `tutorials/blast/axisymmetricPreview` as committed: the average"
      f" cell on the rigid substrate, a {size['Z']*1e6:.0f} um water column "
      f"of radius 50 um, 50 MPa on the top face for {PULSE*1e9:.0f} ns"
      + (" (the water computed up to 20 um above the substrate, its top a "
         "planeWaveInflow boundary that lets in the 1D wave of the whole "
         "column: Allrun's default -inflow)"
         if size["Z"] > 30e-6 and "none" not in size.get("extra", ())
         else "") + ", to "
      f"{endNs:.0f} ns. Level x f: fluid {DEFAULT['h']*1e6:g} f um at the "
      f"cell, {DEFAULT['far']*1e6:g} f um across and "
      f"{DEFAULT['dz']*1e6:g} f um along the column, solid "
      f"{DEFAULT['cell']*1e6:g} f um (membrane 0.8 of it), all scaled "
      "together so that the fluid faces at the cell stay 0.625 of the "
      "membrane faces (the default's ratio; with fluid faces as large as the "
      "solid's the run fails, docs/results/blast.md)"
      + (f"; more Allrun options on every level: `{' '.join(size['extra'])}`"
         if size.get("extra") else "") + ". Probe: the Fig. 10 "
      "element on the cytoplasm-nucleus interface at 75 % of the nucleus "
      f"height; peaks over t <= {win:.0f} ns (the first passage), arrival = "
      f"first probe pressure above {ARRIVAL/1e6:.0f} MPa. Peak memory: the "
      "maximum resident set of cellBlastFoam (/usr/bin/time -v). CPU and "
      "wall: cellBlastFoam's ExecutionTime and ClockTime.")
    w("")
    w(f"| level | fluid h / far, solid [um] | fluid cells | solid elements |"
      f" time steps | dt range [s] | coupling passes/step (mean / max) | "
      f"unconverged steps | CPU to {win:.0f} ns [s] | CPU to end [s] | "
      f"wall to end [s] | peak RSS [MB] | load average (1 min) |")
    w("|---|---|---:|---:|---:|---|---|---:|---:|---:|---:|---:|---:|")
    for r in rows:
        s = r["sizes"]
        end_ = "" if r["rc"] == 0 else f" (FAILED at {r['tLast']*1e9:.2f} ns)"
        cw = f"{r['atWindow'][0]:.1f}" if r["atWindow"] else "-"
        w(f"| x{r['factor']} | {s['h']*1e6:.3g} / {s['far']*1e6:.3g}, "
          f"{s['cell']*1e6:.3g}"
          f" | {r['cells']} | {r['elements']} | {r['steps']} | "
          f"{r['dtMin']:.3g}-{r['dtMax']:.3g} | {r['itMean']:.2f} / "
          f"{r['itMax']} | {r['notConverged']} | {cw} | {r['cpu']:.1f}{end_}"
          f" | {r['wall']:.1f} | {r['rss']:.0f} | "
          + bench.loadColumn(r["load"]) + " |")
    w("")
    w(f"Fig. 10 probe (t <= {win:.0f} ns) and the difference to the finest "
      f"level (x{ref['factor']}): relative [%] for the peaks, [ns] for the "
      "arrival. Strain = ln(stretch_z) (negative: compression along the "
      "shock), its peak and the strain rate's peak are the most negative "
      "values.")
    w("")
    w("| level | CPU [s] | CPU / finest | arrival [ns] | peak p [MPa] (t "
      "[ns]) | peak von Mises [Pa] | peak strain [-] | peak strain rate "
      f"[1/s] | peak {RATE_WINDOW*1e9:g}-ns strain rate [1/s] | interface"
      " von Mises max m-c / c-n [Pa] | largest peak difference [%] |")
    w("|---|---:|---:|---|---|---|---|---|---|---|---:|")
    for r in good:
        d = diffs(r, ref)
        w(f"| x{r['factor']} | {r['cpu']:.1f} | {r['cpu']/ref['cpu']:.2f} | "
          f"{r['arrival']*1e9:.2f} ({d['arrival']:+.2f}) | "
          f"{r['pMax']/1e6:.2f} ({r['tpMax']*1e9:.1f}; {d['pMax']:+.2f} %) |"
          f" {r['vmMax']:.3f} ({d['vmMax']:+.2f} %) | "
          f"{r['strainMin']:.5f} ({d['strainMin']:+.2f} %) | "
          f"{r['rateMin']:.4g} ({d['rateMin']:+.2f} %) | "
          f"{r['rate1nsMin']:.4g} ({d['rate1nsMin']:+.2f} %) | "
          f"{r['vmMC']:.2f} / {r['vmCN']:.2f} ({d['vmMC']:+.1f} / "
          f"{d['vmCN']:+.1f} %) | {d['max']:.2f} |")
    w("")
    rest = [r for r in good if r.get("rest")]
    if rest:
        w(f"At rest after the pulse (t >= {REST*1e9:.0f} ns; issue 17 item "
          "6: |strain_z| below 1e-3 and von Mises below 10 % of its peak):")
        w("")
        w("| level | max \\|strain_z\\| [-] | max von Mises [Pa] (of the "
          "peak) | met |")
        w("|---|---:|---|---|")
        for r in rest:
            ez, vm = r["rest"]
            ok = ez < 1e-3 and vm < 0.1*r["vmMax"]
            w(f"| x{r['factor']} | {ez:.4f} | {vm:.3f} "
              f"({100*vm/r['vmMax']:.0f} %) | {'yes' if ok else 'no'} |")
        w("")
    if len(good) >= 3:
        w("Richardson extrapolation from the three finest levels (Celik et "
          "al. 2008, the GCI procedure; h = the size factor): observed "
          "order p, the extrapolated value, the finest level's error bar "
          "(GCI, 1.25 |change| / (r^p - 1)) and each level's difference "
          "to the extrapolated value. Where the changes alternate or do not"
          " shrink no order is claimed and the error bar is 3 times the "
          "largest change. The raw strain-rate peak across the captured "
          "shock is not extrapolated: it grows as 1/h and has no mesh "
          f"limit; the {RATE_WINDOW*1e9:g}-ns averaged rate is the one to "
          "quote.")
        w("")
        w("| quantity | values (coarse to fine) | observed order | "
          "extrapolated | error bar of the finest [%] | " + " | ".join(
              f"x{r['factor']} to extrapolated [%]" for r in good) + " |")
        w("|---|---|---:|---:|---:|" + "---:|"*len(good))
        for k, lab in QUANTITIES:
            if k not in CONVERGING:
                continue
            R = richardson(good, k)
            if R is None:
                w(f"| {lab} | - | none (fewer than three finite values) | - "
                  "| - | " + " | ".join("-" for _ in good) + " |")
                continue
            vals = " / ".join(f"{v:.4g}" for v in reversed(R.values))
            if R.kind == "monotone":
                cells = " | ".join(f"{100*(r[k]/R.extrapolated - 1):+.2f}"
                                   for r in good)
                w(f"| {lab} | {vals} | {R.p:.2f} | {R.extrapolated:.4g} | "
                  f"{100*R.gci:.2f} | {cells} |")
            else:
                w(f"| {lab} | {vals} | none ({R.kind}) | - | "
                  f"{100*R.gci:.2f} | " + " | ".join("-" for _ in good)
                  + " |")
        w("")
    w("The probe is a point (solid::PointProbe: the element containing it,"
      " element quantities recovered at the point from a patch of elements "
      "of its region), the same reference point on every level up to the "
      "interface's chord:")
    w("")
    w("| level | probe point (r, z) [um] | element (region) | patch "
      "[elements] |")
    w("|---|---|---|---:|")
    for r in rows:
        if "probePoint" in r:
            w(f"| x{r['factor']} | ({r['probePoint'][0]*1e6:.4f}, "
              f"{r['probePoint'][1]*1e6:.4f}) | {r['probeElement']} "
              f"({r['probeRegion']}) | {r['probePatch']} |")
    w("")
    bad = [r for r in rows if r["rc"] != 0]
    for r in bad:
        w(f"Level x{r['factor']} FAILED: cellBlastFoam exit {r['rc']} at "
          f"t = {r['tLast']} s (case {os.path.relpath(r['case'], ROOT)}):")
        w("")
        w("    " + r["error"].replace("\n", "\n    "))
        w("")
    w("CPU split of the time loop (cellBlastFoam):")
    w("")
    for r in good:
        w(f"- x{r['factor']}: {r['split']}")
    w("")
    w("How to read it. The differences are to the finest level run here, "
      "not to the converged answer: the finest level has 0 by definition "
      "and its own error is unknown. If the ladder is in the asymptotic "
      "range with order q and size step r (here about 1.4), the finest "
      "level's own error is about its last change / (r^q - 1): 2.3 times "
      "that change at first order (the scheme's order at the shock front), "
      "the change itself at second order (see the convergence table "
      "below). The lists say which level is the cheapest whose probe peaks "
      "are within a given difference of the finest:")
    w("")
    for key, what in (("max", "all four peaks"), ("pMax", "peak pressure "
                                                      "alone")):
        w(f"- {what}:")
        for e, r in choose(rows, ref, key):
            if r is None:
                w(f"    - within {e} %: no coarser level; only the finest "
                  f"(x{ref['factor']}, {ref['cpu']:.0f} s CPU) or a finer "
                  "one")
            else:
                w(f"    - within {e} %: x{r['factor']} ({r['cells']} fluid "
                  f"cells, {r['elements']} solid elements, {r['cpu']:.0f} s "
                  f"CPU, difference {abs(diffs(r, ref)[key]):.2f} %)")
    w("")
    if len(good) >= 3:
        w("Does the ladder converge? Change of each peak from one level to "
          "the next finer one [%], and the observed order where the changes "
          "shrink (otherwise the finest level is not yet in the asymptotic "
          "range, and its own error is at least of the size of its last "
          "change):")
        w("")
        w("| quantity | " + " | ".join(
            f"x{a['factor']} -> x{b['factor']} [%]"
            for a, b in zip(good, good[1:])) + " | observed order [-] |")
        w("|---|" + "---:|"*(len(good)))
        for lab, ch, order in successive(good):
            w(f"| {lab} | " + " | ".join(f"{c:+.2f}" for c in ch) + " | "
              + (f"{order:.2f}" if order is not None else
                 "none (changes do not shrink, or alternate)") + " |")
        w("")
    w(f"![probe-peak difference against CPU time; probe pressure per "
      f"level]({png})")
    w("")
    w("Commands: per level `./Allrun -noRun -noPlots` with the sizes in a "
      "scratch copy of the tutorial (inputs only), then `/usr/bin/time -v "
      "cellBlastFoam`; e.g. the finest: `" + ref["cmd"] + "`.")
    w("")
    return L, ref


def main():
    ap = bench.arguments(__doc__, os.path.join(HERE, "output"),
                         "20 um column to 25 ns, output in --out")
    ap.add_argument("--factors", default=None,
                    help="size factors, coarsest first, e.g. '1.4 1 0.7'")
    ap.add_argument("--endTime", type=float, default=None, help="[s]")
    ap.add_argument("--allrun", default="",
                    help="more Allrun options for every level, e.g. "
                    "'-shearViscosity 0.4' or '-inflow none'")
    ap.add_argument("--reportOnly", action="store_true",
                    help="no run: the report from the level cases already "
                    "in --out (e.g. after a report error)")
    ap.add_argument("--commit", default=None,
                    help="with --reportOnly: the commit the levels ran "
                    "with (default: from their bench.commit files)")
    args = bench.parse(ap)
    mode = "quick" if args.quick else "full"
    size = dict(SIZES[mode])
    if args.factors:
        size["factors"] = args.factors.split()
    size["extra"] = args.allrun.split()
    if args.endTime:
        size["endTime"] = args.endTime
        size["window"] = min(size["window"], args.endTime)
    out = os.path.abspath(args.out)
    doc = bench.reportPath(args.doc, args.quick, out, ROOT, "blast.md")
    if args.reportOnly:
        # --out must hold the runs to report (adv33 bn06: a missing log
        # named, not that --out holds no run)
        missing = [f for f in size["factors"]
                   if not os.path.isdir(os.path.join(out, f"level_{f}"))]
        if missing:
            raise bench.BenchError(
                "--reportOnly: --out %s holds no run of level%s %s (no "
                "level_<factor> folder): run the benchmark into it first, "
                "or give the --out it ran into"
                % (out, "s" if len(missing) > 1 else "",
                   " ".join(missing)))
    os.makedirs(out, exist_ok=True)
    os.makedirs(os.path.dirname(doc), exist_ok=True)
    env = bench.foamEnv(ROOT)
    start = datetime.datetime.utcnow()
    # the commit of the code that runs (taken before the run)
    commit = bench.commit(ROOT)
    dirty = bench.uncommitted(ROOT, SOURCES)
    if args.reportOnly:
        rows = [parseLevel(f, out, size) for f in size["factors"]]
        cases = [os.path.dirname(r["case"]) for r in rows]
        commit, dirty = bench.stampedCommit(cases, args.commit)
        # the first level's start: its copy of fluidWedgeMesh.py
        start, end = bench.runPeriod(
            [os.path.join(c, "fluidWedgeMesh.py") for c in cases],
            [os.path.join(r["case"], "log.time") for r in rows])
    else:
        rows = []
        for f in size["factors"]:
            rows.append(runLevel(f, out, size, env))
            bench.stampCommit(os.path.join(out, f"level_{f}"), commit, dirty)
        end = datetime.datetime.utcnow()
    if not any(r["rc"] == 0 for r in rows):
        raise bench.BenchError("every level failed")
    png = "blast_cost_vs_error.png"
    lines, ref = report(rows, size, mode, start, png, commit, dirty, end,
                        args.reportOnly)
    plot(rows, ref, size, os.path.join(os.path.dirname(doc), png))
    bench.writeReport(doc, lines)
    if any(r["rc"] != 0 for r in rows):
        sys.exit(1)


if __name__ == "__main__":
    bench.main(main)

#!/usr/bin/python3
"""3D quarter of the blast scene: cost per time step and peak memory per
mesh (not a test; cost only, not accuracy).

Runs tutorials/blast/quarter3D (the average cell in the quarter
[0, 50 um]^2 x [0, 100 um] of the water cube, 50 MPa for 5 ns on top) on
two mesh levels over a short window before the pulse reaches the cell
(default 0-3 ns: the front is still 90 um above it, the interface at rest,
one coupling pass per step), one after the other. Level x f: the fluid
size at the cell (-h 0.5e-6 m), the far fluid size (-far 5e-6 m) and the
solid size (-cell 1.4e-6 m; membrane 5/7 of it) scaled together (the
default's 0.5 um fluid on 1 um membrane faces, docs/results/blast3D.md).
Per level: fluid cells, solid elements, time steps, dt, coupling passes
per step, CPU and wall time of cellBlastFoam, CPU per step and its split,
peak resident memory (/usr/bin/time -v). The probe values are not
compared: before the arrival they are ambient (the accuracy of the 3D
quarter against the preview is docs/results/blast3D.md).

In a scratch copy of the tutorial (inputs only), Allrun -noRun prepares
the case, so that the meshes and fields are its own; then cellBlastFoam
runs on one rank under /usr/bin/time. The first level is then run again
on --ranks N ranks (Allrun -np N -noRun: decomposePar, simple (N 1 1);
mpirun -np N cellBlastFoam -parallel), right after its serial run: the
speed-up side by side.

    bench/blast/quarter3D.py [--quick] [--out DIR] [--doc FILE]
                          [--factors "1 0.7"] [--endTime s] [--ranks 2]

Full: factors 1 0.7 to 3 ns; --quick: 1.4 1 to 1 ns, written into --out
(default bench/blast/output). Writes docs/benchmarks/blastQuarter3D.md
(full) or <out>/blastQuarter3D.md (quick).
"""
import datetime
import os
import re
import sys

from neuronFsi import script  # noqa: E402
script.guard()  # an input's error: one line, exit 1 (fix19k: every script)
from neuronFsi import bench, logs, msh, scratch

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", ".."))
TUTORIAL = os.path.join(ROOT, "tutorials", "blast")
DEFAULT = dict(h=0.5e-6, far=5e-6, cell=1.4e-6)     # [m], Allrun defaults
SIZES = {"full": dict(factors=["1", "0.7"], endTime=3e-9),
         "quick": dict(factors=["1.4", "1"], endTime=1e-9)}
SOURCES, SOURCES_TEXT = bench.measuredCode("blast")


def caseDir(out, f, ranks):
    return os.path.join(out, f"quarter3D_{f}" + (f"_np{ranks}" if ranks > 1
                                                   else ""))


def runLevel(f, out, endTime, env, ranks=1):
    case = caseDir(out, f, ranks)
    # an earlier case of this script only, never a user's folder (adv51
    # n01 (k))
    scratch.outputFolder("quarter3D.py", case, ("@case",))
    scratch.copyInputs(TUTORIAL, case, ("plotBlast.py",))
    c = os.path.join(case, "quarter3D")
    scratch.copyInputs(os.path.join(TUTORIAL, "quarter3D"), c,
                     ("0.orig", "constant", "system", "Allrun"),
                     ("polyMesh", "*.msh"))
    res = bench.runLogged(levelCommand(f, endTime, ranks).split(), c, env,
                          "log.Allrun")
    if res.returncode != 0 or not os.path.isdir(os.path.join(c, "0")):
        bench.fail(res, f"Allrun (prepare) failed in {c}")
    cells = logs.checkMeshCells(os.path.join(c, "log.checkMesh"))
    elements = msh.elementCount(os.path.join(c, "constant", "cell.msh"), {5})
    print(f"3D x{f}: {cells} fluid cells, {elements} solid hexahedra; "
          f"running cellBlastFoam on {ranks} rank(s) ...", flush=True)
    solver = ["cellBlastFoam"] if ranks == 1 else \
        ["mpirun", "-np", str(ranks), "--bind-to", "none", "cellBlastFoam",
         "-parallel"]
    bench.runTimed(c, solver, env, "log.cellBlastFoam")
    return parseLevel(f, out, endTime, ranks)


def levelCommand(f, endTime, ranks):
    """the tutorial's Allrun that prepares level x f (not run)"""
    s = {k: v*float(f) for k, v in DEFAULT.items()}
    # the whole water column (-inflow none), as docs/benchmarks/
    # blastQuarter3D.md was measured
    return (f"./Allrun -noRun -noPlots -inflow none -h {s['h']:.6g}"
            f" -far {s['far']:.6g}"
            f" -cell {s['cell']:.6g} -endTime {endTime:g}"
            + (f" -np {ranks}" if ranks > 1 else ""))


def parseLevel(f, out, endTime, ranks=1):
    """the results of a level run in out/quarter3D_f[_npN]"""
    c = os.path.join(caseDir(out, f, ranks), "quarter3D")
    s = {k: v*float(f) for k, v in DEFAULT.items()}
    cmd = levelCommand(f, endTime, ranks)
    cells = logs.checkMeshCells(os.path.join(c, "log.checkMesh"))
    elements = msh.elementCount(os.path.join(c, "constant", "cell.msh"), {5})
    timeV = logs.timeV(os.path.join(c, "log.time"))
    rc = -1 if timeV["status"] is None else timeV["status"]
    log = os.path.join(c, "log.cellBlastFoam")
    cpu, wall = logs.executionTime(log)
    split = logs.cpuSplit(log)
    tLast = logs.lastTime(log)
    loop = float(re.search(r"time loop ([0-9.]+) s", split).group(1)) \
        if split else float("nan")
    r = dict(factor=f, ranks=ranks, sizes=s, cells=cells, elements=elements,
             rc=rc, tLast=tLast, cpu=cpu, wall=wall, loop=loop,
             rss=timeV["rss"]/1024, split=split, load=bench.loadAverage(c),
             cmd=cmd, **bench.couplingStatistics(c))
    print(f"3D x{f}: exit {rc}, {r['steps']} steps to "
          f"{tLast} s, dt {r['dtMin']:.3g}-{r['dtMax']:.3g} s, CPU {cpu:.1f}"
          f" s ({loop/max(r['steps'], 1):.3f} s per step in the loop), "
          f"wall {wall:.1f} s, peak RSS {r['rss']:.0f} MB", flush=True)
    return r


def main():
    ap = bench.arguments(__doc__, os.path.join(HERE, "output"))
    ap.add_argument("--factors", default=None)
    ap.add_argument("--endTime", type=float, default=None, help="[s]")
    ap.add_argument("--ranks", type=int, default=2,
                    help="the first level also on this many MPI ranks "
                    "(1: not)")
    ap.add_argument("--reportOnly", action="store_true",
                    help="no run: the report from the level cases in --out")
    ap.add_argument("--commit", default=None,
                    help="with --reportOnly: the commit the levels ran with "
                    "(default: their bench.commit files)")
    args = bench.parse(ap)
    mode = "quick" if args.quick else "full"
    size = dict(SIZES[mode])
    if args.factors:
        size["factors"] = args.factors.split()
    if args.endTime:
        size["endTime"] = args.endTime
    out = os.path.abspath(args.out)
    doc = bench.reportPath(args.doc, args.quick, out, ROOT,
                           "blastQuarter3D.md")
    os.makedirs(out, exist_ok=True)
    env = bench.foamEnv(ROOT)
    start = datetime.datetime.utcnow()
    commit = bench.commit(ROOT)
    dirty = bench.uncommitted(ROOT, SOURCES)
    f0 = size["factors"][0]
    if args.reportOnly:
        rows = [parseLevel(f, out, size["endTime"])
                for f in size["factors"]]
        par = parseLevel(f0, out, size["endTime"], args.ranks) \
            if args.ranks > 1 else None
        cases = [os.path.join(out, f"quarter3D_{f}")
                 for f in size["factors"]]
        commit, dirty = bench.stampedCommit(cases, args.commit)
        # the first level's start: its copy of plotBlast.py
        start, endT = bench.runPeriod(
            [os.path.join(c, "plotBlast.py") for c in cases],
            [os.path.join(c, "quarter3D", "log.time") for c in cases])
    else:
        rows, par = [], None
        for f in size["factors"]:
            rows.append(runLevel(f, out, size["endTime"], env))
            if f == f0 and args.ranks > 1:
                par = runLevel(f, out, size["endTime"], env, args.ranks)
            for n in {1, args.ranks if f == f0 else 1}:
                bench.stampCommit(caseDir(out, f, n), commit, dirty)
        endT = datetime.datetime.utcnow()
    end = size["endTime"]*1e9
    L = []
    w = L.append
    w("# 3D quarter of the blast scene: cost per time step and peak memory")
    w("")
    w("**Cost only, not accuracy**: the window 0-"
      f"{end:g} ns ends long before the pulse reaches the cell (about 60 "
      "ns), so the interface is at rest and the probe is ambient; what is "
      "measured is the price of a time step on each mesh. The accuracy of "
      "the 3D quarter: docs/results/blast3D.md; of the axisymmetric "
      "preview per mesh: [blast.md](blast.md).")
    w("")
    w(bench.levelsWrittenBy("bench/blast/quarter3D.py", mode, start, endT,
                            commit, dirty, SOURCES_TEXT, args.reportOnly)
      + ", on "
      f"{os.cpu_count()} cores shared with other engineers' builds and "
      "runs (load average at the end of each level in the table): the "
      "CPU time is the one-core cost, wall times are noisy.")
    w("")
    w("Case `tutorials/blast/quarter3D` as committed (100 um box, 5 ns "
      "pulse of 50 MPa, robin coupling, one rank). Level x f: fluid "
      f"{DEFAULT['h']*1e6:g} f um at the cell growing to "
      f"{DEFAULT['far']*1e6:g} f um, solid {DEFAULT['cell']*1e6:g} f um "
      "(membrane 5/7 of it tangentially). CPU and wall: cellBlastFoam's "
      "ExecutionTime and ClockTime (start-up included); per step: the time "
      "loop's CPU over the steps. Peak memory: maximum resident set "
      "(/usr/bin/time -v).")
    w("")
    w("| level | fluid h / far, solid [um] | fluid cells | solid hexahedra |"
      " time steps | dt range [s] | median dt [s] | coupling passes/step (mean / max) | "
      "unconverged steps | CPU [s] | CPU per step [s] | CPU per step per "
      "fluid cell [us] | wall [s] | peak RSS [MB] | load average (1 min) |")
    w("|---|---|---:|---:|---:|---|---:|---|---:|---:|---:|---:|---:|---:|"
      "---:|")
    for r in rows:
        s = r["sizes"]
        fail = "" if r["rc"] == 0 else \
            f" (FAILED, exit {r['rc']}, at {r['tLast']} s)"
        per = r["loop"]/max(r["steps"], 1)
        w(f"| x{r['factor']} | {s['h']*1e6:.3g} / {s['far']*1e6:.3g}, "
          f"{s['cell']*1e6:.3g} | {r['cells']} | {r['elements']} | "
          f"{r['steps']} | {r['dtMin']:.3g}-{r['dtMax']:.3g} | "
          f"{r['dtMedian']:.4g} | "
          f"{r['itMean']:.2f} / {r['itMax']} | {r['notConverged']} | "
          f"{r['cpu']:.1f}{fail} | {per:.4f} | {1e6*per/r['cells']:.2f} | "
          f"{r['wall']:.1f} | {r['rss']:.0f} | "
          + bench.loadColumn(r["load"]) + " |")
    w("")
    if len(rows) > 1 and all(r["rc"] == 0 for r in rows):
        a, b = rows[0], rows[-1]
        pa, pb = a["loop"]/a["steps"], b["loop"]/b["steps"]
        w(f"From x{a['factor']} to x{b['factor']}: fluid cells x "
          f"{b['cells']/a['cells']:.2f}, solid elements x "
          f"{b['elements']/a['elements']:.2f}, CPU per step x {pb/pa:.2f}, "
          f"median time step x {b['dtMedian']/a['dtMedian']:.2f}, so CPU "
          "per simulated ns x "
          f"{pb/pa*a['dtMedian']/b['dtMedian']:.2f}; peak memory x "
          f"{b['rss']/a['rss']:.2f}. At this cost per step and median step "
          "(at rest: the arrival adds coupling passes and may shorten the "
          "step), 90 ns would take about "
          f"{90e-9/a['dtMedian']*pa:.0f} s (x{a['factor']}) and "
          f"{90e-9/b['dtMedian']*pb:.0f} s (x{b['factor']}) of CPU.")
        w("")
    if par:
        a = rows[0]
        pa, pp = a["loop"]/a["steps"], par["loop"]/par["steps"]
        w(f"Level x{f0} on 1 and {par['ranks']} ranks, one after the other "
          "(the fluid decomposed by Allrun -np, simple "
          f"({par['ranks']} 1 1); the solid whole on every rank). Time loop "
          "of rank 0 (an MPI rank that waits spins, so its CPU is its wall "
          "time):")
        w("")
        w("| ranks | time steps | time loop [s] | per step [s] | speed-up "
          "[-] | parallel efficiency [%] | wall [s] | peak RSS of one rank "
          "[MB] | load average (1 min) |")
        w("|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
        for r in (a, par):
            per = r["loop"]/r["steps"]
            w(f"| {r['ranks']} | {r['steps']} | {r['loop']:.2f} | "
              f"{per:.4f} | {pa/per:.2f} | {100*pa/per/r['ranks']:.0f} | "
              f"{r['wall']:.1f} | {r['rss']:.0f} | {r['load'][0]:.2f} |")
        w("")
        w(f"- {par['ranks']} ranks: {par['split']}")
        w("")
    w("CPU split of the time loop (cellBlastFoam):")
    w("")
    for r in rows:
        w(f"- x{r['factor']}: {r['split']}")
    w("")
    w("Commands: per level the tutorial's Allrun (prepare only)"
      " in a scratch copy, then `/usr/bin/time -v cellBlastFoam`; e.g. `"
      + rows[-1]["cmd"] + "`"
      + (f"; on {par['ranks']} ranks `{par['cmd']}`, then `mpirun -np "
         f"{par['ranks']} --bind-to none cellBlastFoam -parallel`"
         if par else "") + ".")
    w("")
    bench.writeReport(doc, L)
    if any(r["rc"] != 0 for r in rows + ([par] if par else [])):
        sys.exit(1)


if __name__ == "__main__":
    bench.main(main)

#!/usr/bin/python3
"""Fluid benchmark of rhoRiemannFoam (not a test).

Three measurements in one run, each pair back to back so that the ratios
survive the load of a shared machine:
  1. cost per cell per flux evaluation, ideal-gas Sod states on a 1D and a
     3D mesh, fixed deltaT and number of steps: rhoRiemannFoam (HLLC, MUSCL,
     SSPRK3 = 3 flux evaluations per step, and Euler = 1) against the stock
     rhoCentralFoam (Kurganov-Tadmor, 1 flux evaluation per step), timed from
     the solvers' ExecutionTime (CPU time) between the first and last step;
  2. L1 error against solver time for the 50 MPa water shock
     (tutorials/verification/waterShock50MPa) over meshes and every
     combination of Riemann solver, limiter and Runge-Kutta scheme;
  3. 1 rank against 2 ranks (decomposePar simple, mpirun -np 2) on a 3D box
     of about 1e6 cells, fixed number of steps: wall time of the time loop,
     speed-up, parallel efficiency, peak resident memory of every rank.

Writes the tables to the markdown file --doc (default
docs/benchmarks/fluid.md, or <out>/fluid.md with --quick) with the plot of
error against time next to it, and prints them. Cases run in --out
(default bench/fluid/output, ignored by git).
"""
import argparse
import datetime
import itertools
import math
import os
import re
import shutil
import subprocess
import time

import sys
try:
    from neuronFsi import script
except ImportError:
    sys.exit("bench/fluid/run.py: error: the project's Python package neuronFsi "
             "is not found: source the project's etc/bashrc first")
script.guard()  # an input's error: one line, exit 1 (adv33)
from neuronFsi import bench, scratch

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
TUTORIALS = os.path.join(ROOT, "tutorials", "verification")
STOCK_OVERLAY = os.path.join(ROOT, "tests", "verification",
                             "rhoCentralFoamSod")

# Sizes: (1D cells, 1D steps, 3D cells per edge, 3D steps,
#         water meshes, parallel cells per edge, parallel steps, repeats)
SIZES = {
    "full": dict(n1D=20000, steps1D=100, n3D=50, steps3D=50,
                 water=[100, 200, 400, 800, 1600, 3200],
                 nPar=100, stepsPar=20, repeats=2),
    "quick": dict(n1D=5000, steps1D=50, n3D=24, steps3D=20,
                  water=[100, 200, 400], nPar=40, stepsPar=10, repeats=1),
}

# Fixed time step: Courant number on the fastest Sod signal speed
# (post-shock |u| + c < 700 m/s) of about 0.14, stable for both solvers
SOD_SPEED = 1000.0      # [m/s]
SOD_CO = 0.2            # [-]
SOD_LENGTH = 10.0       # tube length [m]


ENV = bench.foamEnv(ROOT)


def foam(cmd, cwd, log=None):
    """Run a shell command in the project environment; raise on failure."""
    res = bench.runLogged(["bash", "-c", cmd], cwd, ENV, log)
    if res.returncode != 0:
        bench.fail(res, f"'{cmd}' failed in {cwd} (exit {res.returncode})")
    return res.stdout


def set_entries(case, dictFile, entries):
    """foamDictionary -set of several key=value entries of one file."""
    for key, value in entries.items():
        foam(f"foamDictionary -entry '{key}' -set '{value}' {dictFile}"
             " > /dev/null", case)


def copy_tutorial(name, dst, stock=False):
    """Scratch copy of a verification tutorial (without its mesh); with
    stock, the rhoCentralFoam overlay on top."""
    # never a user's folder: only this script's earlier output is emptied
    # (neuronFsi.scratch.outputFolder; adv51 n01)
    scratch.outputFolder("run.py", dst, ("@case",))
    scratch.copyInputs(os.path.join(TUTORIALS, name), dst,
                     ("0.orig", "system", "constant"), ("polyMesh",))
    if stock:
        shutil.copytree(STOCK_OVERLAY, dst, dirs_exist_ok=True)
    app = "rhoCentralFoam" if stock else "rhoRiemannFoam"
    foam(f"sed -i 's/^application .*/application {app};/'"
         " system/controlDict", dst)


def box_mesh_dict(n):
    """blockMeshDict of a cube of side SOD_LENGTH with n^3 cells, every
    outer face transmissive (patch 'sides')."""
    h = SOD_LENGTH/2
    return f"""FoamFile
{{
    version 2.0; format ascii; class dictionary; object blockMeshDict;
}}
scale 1;
vertices
(
    (-{h} -{h} -{h}) ({h} -{h} -{h}) ({h} {h} -{h}) (-{h} {h} -{h})
    (-{h} -{h} {h}) ({h} -{h} {h}) ({h} {h} {h}) (-{h} {h} {h})
);
blocks (hex (0 1 2 3 4 5 6 7) ({n} {n} {n}) simpleGrading (1 1 1));
boundary
(
    sides
    {{
        type patch;
        faces ((0 4 7 3) (1 2 6 5) (0 1 5 4) (3 7 6 2) (0 3 2 1) (4 5 6 7));
    }}
);
"""


def sod_case(dst, n, dim, steps, stock=False, timeScheme="SSPRK3",
             meshFrom=None):
    """Sod case on n cells (1D) or n^3 cells (3D), fixed deltaT, `steps`
    steps and no writes; the mesh copied from the case meshFrom if given.
    Returns the number of cells."""
    copy_tutorial("sodIdealGas", dst, stock)
    dx = SOD_LENGTH/n
    dt = SOD_CO*dx/SOD_SPEED
    if dim == 1:
        foam(f"sed -i 's/^nCells .*/nCells {n};/' system/blockMeshDict", dst)
    else:
        with open(os.path.join(dst, "system", "blockMeshDict"), "w") as f:
            f.write(box_mesh_dict(n))
    # One line edits: foamDictionary would expand the riemannProblemDict
    # $variables of controlDict
    for key, value in (("endTime", f"{steps*dt:.12g}"),
                       ("deltaT", f"{dt:.12g}"),
                       ("writeControl", "timeStep"),
                       ("writeInterval", f"{10*steps}"),
                       ("writeFormat", "binary"),
                       ("adjustTimeStep", "no")):
        foam(f"sed -i 's/^{key} .*/{key} {value};/' system/controlDict", dst)
    if not stock:
        set_entries(dst, "system/fvSolution",
                    {"riemann/timeScheme": timeScheme})
    foam("rm -rf 0 && cp -r 0.orig 0", dst)
    if meshFrom:
        shutil.copytree(os.path.join(meshFrom, "constant", "polyMesh"),
                        os.path.join(dst, "constant", "polyMesh"))
    else:
        foam("blockMesh", dst, "log.blockMesh")
    foam("setRiemannProblem", dst, "log.setRiemannProblem")
    return n if dim == 1 else n**3


def fresh(case):
    """The case as its first run found it: the time directories after the
    initial one (also in processor*/) and postProcessing/ removed. Our
    solvers write their end time, and a second run of the case (a repeat,
    the profile) continued from it (startFrom latestTime) and stopped:
    "would compute nothing" (adv33/adv34 bn10: '(perf record failed: no
    profile)')"""
    foam("foamListTimes -rm > /dev/null && rm -rf postProcessing"
         " && if [ -d processor0 ]; then foamListTimes -processor -rm"
         " > /dev/null; fi", case)


def run_solver(case, app, nProcs=1):
    """Run the solver from the case's initial time (fresh); return
    per-step wall stamps [s] (taken when each ExecutionTime line arrives),
    the ExecutionTime values [s], the peak resident memory of every rank
    [MB], the wall time [s] and, serial, the CPU time [s] of the
    process."""
    fresh(case)
    if nProcs == 1:
        cmd = [app]
    else:
        cmd = ["mpirun", "-np", str(nProcs), "--bind-to", "none", "sh", "-c",
               "exec /usr/bin/time -f %M -o rss.$OMPI_COMM_WORLD_RANK"
               f" {app} -parallel"]
    stamps, cpu = [], []
    start = time.perf_counter()
    with open(os.path.join(case, f"log.{app}.{nProcs}"), "w") as log:
        proc = subprocess.Popen(cmd, cwd=case, env=ENV,
                                stdout=subprocess.PIPE,
                                stderr=subprocess.STDOUT, text=True,
                                bufsize=1)
        for line in proc.stdout:
            if line.startswith("ExecutionTime"):
                stamps.append(time.perf_counter())
                cpu.append(float(line.split()[2]))
            log.write(line)
        _, status, usage = os.wait4(proc.pid, 0)
    wall = time.perf_counter() - start
    if status != 0:
        raise RuntimeError(f"{' '.join(cmd)} failed in {case}"
                           f" (status {status}), see its log")
    if nProcs == 1:
        rss = [usage.ru_maxrss/1024]
    else:
        rss = []
        for rank in range(nProcs):
            with open(os.path.join(case, f"rss.{rank}")) as f:
                rss.append(float(f.read().split()[-1])/1024)
    return dict(stamps=stamps, cpu=cpu, rss=rss, wall=wall,
                processCpu=usage.ru_utime + usage.ru_stime)


def loop_times(r):
    """CPU and wall time [s] of the time loop after the first step (which
    includes lazily built mesh data), and the number of steps timed."""
    n = len(r["cpu"]) - 1
    return r["cpu"][-1] - r["cpu"][0], r["stamps"][-1] - r["stamps"][0], n


def loadavg():
    with open("/proc/loadavg") as f:
        return " ".join(f.read().split()[:3])


# ---------------------------------------------------------------- part 1

def cost_per_flux(out, size, md):
    """Cost per cell per flux evaluation, ours against rhoCentralFoam."""
    contenders = [("rhoRiemannFoam HLLC MUSCL SSPRK3", False, "SSPRK3", 3),
                  ("rhoRiemannFoam HLLC MUSCL Euler", False, "Euler", 1),
                  ("rhoCentralFoam Kurganov vanLeer", True, None, 1)]
    rows = []
    for dim, n, steps in ((1, size["n1D"], size["steps1D"]),
                          (3, size["n3D"], size["steps3D"])):
        cases = []
        for name, stock, ts, nEval in contenders:
            dst = os.path.join(out, "cost", f"{dim}D_{name.split()[0]}"
                                            f"_{ts or 'stock'}")
            nCells = sod_case(dst, n, dim, steps, stock, ts or "SSPRK3")
            cases.append((name, dst, nEval, nCells))
            if dim == 3 and ts == "SSPRK3":
                profileCase = dst
        best = {}
        # Interleaved repeats, the minimum of each: the least disturbed
        for rep in range(size["repeats"]):
            for name, dst, nEval, nCells in cases:
                app = "rhoCentralFoam" if "Central" in name \
                    else "rhoRiemannFoam"
                r = run_solver(dst, app)
                cpu, wall, nSteps = loop_times(r)
                prev = best.get(name)
                if prev is None or cpu < prev["cpu"]:
                    best[name] = dict(cpu=cpu, wall=wall, nSteps=nSteps,
                                      rss=r["rss"][0])
        stockName = cases[-1][0]
        stockStep = best[stockName]["cpu"]/best[stockName]["nSteps"]
        stockEval = stockStep/cases[-1][3]*1e9
        for name, dst, nEval, nCells in cases:
            b = best[name]
            perStep = b["cpu"]/b["nSteps"]
            perEval = perStep/nEval/nCells*1e9
            rows.append((f"{dim}D", nCells, name, nEval, b["nSteps"],
                         perStep*1e3, perEval, perEval/stockEval,
                         perStep/stockStep, b["wall"]/b["nSteps"]*1e3,
                         b["rss"]))
    head = ("| mesh | cells | solver | flux evals/step | steps timed "
            "| CPU/step [ms] | CPU/(cell eval) [ns] | ratio per eval "
            "| ratio per step | wall/step [ms] | peak RSS [MB] "
            "| peak RSS per cell [KB] |")
    lines = [head, "|" + "---|"*12]
    for r in rows:
        lines.append(f"| {r[0]} | {r[1]} | {r[2]} | {r[3]} | {r[4]} "
                     f"| {r[5]:.2f} | {r[6]:.1f} | {r[7]:.2f} | {r[8]:.2f} "
                     f"| {r[9]:.2f} | {r[10]:.0f} | {r[10]*1024/r[1]:.2f} |")
    md.append("\n".join(lines))
    print("\n".join(lines), flush=True)
    md.append(PROFILE.format(**size))
    profile(profileCase, md)
    return rows


def profile(case, md):
    """Sampling profile (perf, cpu-clock) of rhoRiemannFoam on a case:
    share of the CPU time per library and the hottest functions."""
    if not shutil.which("perf"):
        md.append("(perf not found: no profile)")
        return
    data = os.path.join(case, "perf.data")
    fresh(case)     # the case was run to its end by the timings
    try:
        foam(f"perf record -e cpu-clock -o {data} rhoRiemannFoam", case,
             "log.perf")
    except RuntimeError:
        # why: the solver's error or perf's, named (was: "perf record
        # failed", the cause hidden)
        with open(os.path.join(case, "log.perf"), errors="replace") as f:
            text = f.read()
        m = re.search(r"FOAM FATAL.*?\n(.+)", text) or \
            re.search(r"^(.*(?:[Ee]rror|failed|not permitted).*)$", text,
                      re.M)
        md.append("(perf record -e cpu-clock rhoRiemannFoam failed in %s: "
                  "%s; see %s: no profile)"
                  % (case, m.group(1).strip() if m else "no error message",
                     os.path.join(case, "log.perf")))
        return
    tables = []
    for sort, title, n in (("dso", "library", 8),
                           ("dso,sym", "function", 14)):
        out = foam(f"perf report -i {data} --no-children --stdio"
                   f" --sort {sort} 2> /dev/null", case)
        rows = [l.split(None, 1) for l in out.splitlines()
                if re.match(r"\s+\d+\.\d+%", l)][:n]
        lines = [f"| share of CPU samples | {title} |", "|---|---|"]
        for pct, what in rows:
            what = re.sub(r"\s+\[\.\]\s+", ": ", what.strip())
            what = what.replace("|", "\\|")
            lines.append(f"| {pct} | `{what}` |")
        tables.append("\n".join(lines))
    md.extend(tables)
    print("\n\n".join(tables), flush=True)


# ---------------------------------------------------------------- part 2

WATER_SCHEMES = {
    "riemannSolver": ["HLLC", "HLL", "rusanov"],
    "limiter": ["MUSCL", "vanLeer", "upwind"],
    "timeScheme": ["SSPRK3", "SSPRK2"],
}


def water_errors(out, size, md, docDir):
    """L1 errors and solver time of the 50 MPa water shock over meshes and
    every combination of scheme options."""
    results = []
    combos = list(itertools.product(*WATER_SCHEMES.values()))
    for nCells in size["water"]:
        dst = os.path.join(out, "water", f"n{nCells}")
        copy_tutorial("waterShock50MPa", dst)
        foam(f"sed -i 's/^nCells .*/nCells {nCells};/'"
             " system/blockMeshDict", dst)
        foam("rm -rf 0 && cp -r 0.orig 0 && blockMesh", dst, "log.blockMesh")
        foam("setRiemannProblem", dst, "log.setRiemannProblem")
        for solver, limiter, ts in combos:
            vector = limiter if limiter == "upwind" else limiter + "V"
            set_entries(dst, "system/fvSolution",
                        {"riemann/riemannSolver": solver,
                         "riemann/timeScheme": ts})
            set_entries(dst, "system/fvSchemes",
                        {"interpolationSchemes/reconstruct(rho)": limiter,
                         "interpolationSchemes/reconstruct(U)": vector,
                         "interpolationSchemes/reconstruct(p)": limiter})
            foam("foamListTimes -rm > /dev/null && rm -rf postProcessing",
                 dst)
            r = run_solver(dst, "rhoRiemannFoam")
            foam("riemannError -latestTime", dst, "log.riemannError")
            base = os.path.join(dst, "postProcessing", "riemannError")
            latest = max(os.listdir(base), key=float)
            with open(os.path.join(base, latest, "errors.dat")) as f:
                v = [float(x) for x in f.read().split("\n")[1].split()]
            results.append(dict(scheme=f"{solver} {limiter} {ts}",
                                cells=nCells, rho=v[1], u=v[2], p=v[3],
                                steps=len(r["cpu"]), cpu=r["processCpu"],
                                wall=r["wall"]))
    byScheme = {}
    for r in results:
        byScheme.setdefault(r["scheme"], []).append(r)

    # Summary: finest mesh, observed order of L1(p), sorted by error
    finest = size["water"][-1]
    lines = ["| Riemann solver, limiter, time scheme "
             f"| L1(p) on {finest} cells [Pa] | L1(rho) [kg/m^3] "
             "| L1(u) [m/s] | mean order of L1(p) | steps | CPU [s] "
             "| wall [s] |", "|" + "---|"*8]
    for scheme, rs in sorted(byScheme.items(), key=lambda kv: kv[1][-1]["p"]):
        f = rs[-1]
        orders = [math.log(a["p"]/b["p"])/math.log(b["cells"]/a["cells"])
                  for a, b in zip(rs[:-1], rs[1:])]
        lines.append(f"| {scheme} | {f['p']:.4g} | {f['rho']:.4g} "
                     f"| {f['u']:.4g} | {sum(orders)/len(orders):.2f} "
                     f"| {f['steps']} | {f['cpu']:.2f} | {f['wall']:.2f} |")
    summary = "\n".join(lines)

    # Cheapest option for a target error: smallest time reaching it
    lines = ["| target L1(p) [Pa] | cheapest option | cells | L1(p) [Pa] "
             "| CPU [s] |", "|---|---|---|---|---|"]
    ps = sorted(r["p"] for r in results)
    for target in sorted({float(f"{p:.1g}") for p in
                          (ps[0]*1.5, ps[len(ps)//8], ps[len(ps)//3],
                           ps[len(ps)*2//3])}):
        ok = [r for r in results if r["p"] <= target]
        if ok:
            r = min(ok, key=lambda r: r["cpu"])
            lines.append(f"| {target:.1e} | {r['scheme']} | {r['cells']} "
                         f"| {r['p']:.3g} | {r['cpu']:.3f} |")
    cheapest = "\n".join(lines)

    lines = ["| Riemann solver, limiter, time scheme | cells "
             "| L1(rho) [kg/m^3] | L1(u) [m/s] | L1(p) [Pa] | steps "
             "| CPU [s] | wall [s] |", "|" + "---|"*8]
    for scheme, rs in byScheme.items():
        for r in rs:
            lines.append(f"| {scheme} | {r['cells']} | {r['rho']:.4g} "
                         f"| {r['u']:.4g} | {r['p']:.4g} | {r['steps']} "
                         f"| {r['cpu']:.3f} | {r['wall']:.3f} |")
    full = "\n".join(lines)
    print(summary + "\n\n" + cheapest, flush=True)
    plot = plot_water(byScheme, docDir)
    md.extend([summary, cheapest, f"![L1 error against time]({plot})",
               "All runs:", full])
    return results


def plot_water(byScheme, docDir):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    colours = dict(zip(WATER_SCHEMES["riemannSolver"], ["C0", "C1", "C2"]))
    styles = dict(zip(WATER_SCHEMES["limiter"], ["-", "--", ":"]))
    markers = dict(zip(WATER_SCHEMES["timeScheme"], ["o", "s"]))
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.5))
    for scheme, rs in byScheme.items():
        solver, limiter, ts = scheme.split()
        for ax, key in zip(axes, ("p", "rho")):
            ax.loglog([r["cpu"] for r in rs], [r[key] for r in rs],
                      color=colours[solver], linestyle=styles[limiter],
                      marker=markers[ts], markersize=3, linewidth=1,
                      label=scheme)
    axes[0].set_ylabel("L1 error of p [Pa]")
    axes[1].set_ylabel("L1 error of rho [kg/m^3]")
    for ax in axes:
        ax.set_xlabel("solver CPU time [s]")
        ax.grid(True, which="both", alpha=0.3)
    axes[1].legend(fontsize=6, ncol=2)
    fig.suptitle("50 MPa water shock tube: L1 error against time"
                 " (meshes " + ", ".join(str(r["cells"]) for r in
                                         next(iter(byScheme.values())))
                 + " cells)", fontsize=10)
    fig.tight_layout()
    name = "fluid_water_error_vs_time.png"
    fig.savefig(os.path.join(docDir, name), dpi=80)
    return name


# ---------------------------------------------------------------- part 3

def parallel(out, size, md):
    """1 rank against 2 ranks on a 3D box; the stock rhoCentralFoam on the
    same mesh as a control of what the machine allows."""
    n, steps = size["nPar"], size["stepsPar"]
    solvers = (("rhoRiemannFoam", False), ("rhoCentralFoam", True))
    cases = []
    for app, stock in solvers:
        dst = os.path.join(out, "parallel", f"{app}_box{n}")
        nCells = sod_case(dst, n, 3, steps, stock,
                          meshFrom=cases[0] if cases else None)
        with open(os.path.join(dst, "system", "decomposeParDict"), "w") as f:
            f.write("FoamFile { version 2.0; format ascii; class dictionary;"
                    " object decomposeParDict; }\nnumberOfSubdomains 2;\n"
                    "method simple;\ncoeffs { n (2 1 1); }\n")
        foam("decomposePar -force", dst, "log.decomposePar")
        cases.append(dst)
    runs = {}
    # Interleaved repeats, the least wall time of each
    for rep in range(size["repeats"]):
        for (app, _), dst in zip(solvers, cases):
            for nProcs in (1, 2):
                r = run_solver(dst, app, nProcs)
                cpu, wall, nSteps = loop_times(r)
                key = (app, nProcs)
                if key not in runs or wall < runs[key]["wall"]:
                    runs[key] = dict(wall=wall, cpu=cpu, nSteps=nSteps,
                                     rss=r["rss"], total=r["wall"])
    lines = ["| solver | ranks | cells | steps timed | wall/step [s] "
             "| CPU/step rank 0 [s] | speed-up [-] "
             "| parallel efficiency [%] | peak RSS per rank [MB] "
             "| peak RSS sum [MB] | solver wall incl. start-up [s] |",
             "|" + "---|"*11]
    for (app, nProcs), r in runs.items():
        w1 = runs[(app, 1)]["wall"]/runs[(app, 1)]["nSteps"]
        w = r["wall"]/r["nSteps"]
        r["speedup"] = w1/w
        lines.append(f"| {app} | {nProcs} | {nCells} | {r['nSteps']} "
                     f"| {w:.3f} | {r['cpu']/r['nSteps']:.3f} | {w1/w:.2f} "
                     f"| {100*w1/w/nProcs:.0f} "
                     f"| {', '.join(f'{x:.0f}' for x in r['rss'])} "
                     f"| {sum(r['rss']):.0f} | {r['total']:.1f} |")
    table = "\n".join(lines)
    print(table, flush=True)
    md.append(table)
    return runs


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("--quick", action="store_true",
                    help="small sizes (about 2 minutes)")
    ap.add_argument("--out", default=os.path.join(ROOT, "bench", "fluid",
                                                  "output"))
    ap.add_argument("--doc", help="markdown file to write")
    ap.add_argument("--parts", default="123",
                    help="which measurements, e.g. 13")
    args = bench.parse(ap)
    if not args.parts or any(c not in "123" for c in args.parts):
        ap.error("--parts '%s': not a selection of the measurements 1, 2, 3"
                 " (e.g. 13)" % args.parts)
    size = SIZES["quick" if args.quick else "full"]
    doc = bench.reportPath(args.doc, args.quick, args.out, ROOT, "fluid.md")
    docDir = os.path.dirname(os.path.abspath(doc))
    os.makedirs(args.out, exist_ok=True)
    os.makedirs(docDir, exist_ok=True)

    start = time.perf_counter()
    load0 = loadavg()
    commit = bench.commit(ROOT)
    parts = {}
    summary = []
    if "1" in args.parts:
        parts[1] = []
        for r in cost_per_flux(args.out, size, parts[1]):
            if "SSPRK3" in r[2]:
                summary.append(
                    f"- cost per cell per flux evaluation, HLLC MUSCL SSPRK3"
                    f" over rhoCentralFoam, {r[0]} ({r[1]} cells):"
                    f" {r[7]:.2f} (target <= 0.3: "
                    f"{'met' if r[7] <= 0.3 else 'NOT met'}); per time step"
                    f" {r[8]:.2f} (target <= 1.0: "
                    f"{'met' if r[8] <= 1.0 else 'NOT met'}); peak memory"
                    f" {r[10]*1024/r[1]:.2f} KB per cell (target <= 1)")
    if "2" in args.parts:
        parts[2] = []
        water_errors(args.out, size, parts[2], docDir)
    if "3" in args.parts:
        parts[3] = []
        runs = parallel(args.out, size, parts[3])
        ours = runs[("rhoRiemannFoam", 2)]["speedup"]
        stock = runs[("rhoCentralFoam", 2)]["speedup"]
        summary.append(f"- 2 ranks on {size['nPar']}^3 cells: speed-up"
                       f" {ours:.2f}, parallel efficiency {50*ours:.0f} %"
                       f" (target >= 80 %: "
                       f"{'met' if ours >= 1.6 else 'NOT met'}); the stock"
                       f" rhoCentralFoam in the same run: {50*stock:.0f} %")
    elapsed = time.perf_counter() - start
    write_doc(doc, args, size, parts, summary, commit, load0,
              loadavg(), elapsed)
    print("\n" + "\n".join(summary))
    print(f"\nwrote {doc} ({elapsed:.0f} s)")


def write_doc(doc, args, size, parts, summary, commit, load0, load1,
              elapsed):
    cpu = next((l.split(":", 1)[1].strip() for l in open("/proc/cpuinfo")
                if l.startswith("model name")), "?")
    text = [f"# Fluid benchmark: rhoRiemannFoam\n",
            f"Generated by `bench/fluid/run.py{' --quick' if args.quick else ''}`"
            f" on {datetime.date.today()} at commit {commit}, in"
            f" {elapsed/60:.1f} min. Machine: {os.cpu_count()} cores"
            f" ({cpu}), shared with other users: load average"
            f" {load0} at the start, {load1} at the end"
            " (1, 5, 15 min). Absolute times are noisy (other jobs run"
            " concurrently); the pairs are measured back to back in the"
            " same run, so read the ratios.\n", "\n".join(summary)]
    if 1 in parts:
        text.append(PART1.format(**size, dt=SOD_CO, u=SOD_SPEED))
        text.extend(parts[1])
    if 2 in parts:
        text.append(PART2.format(meshes=", ".join(map(str, size["water"]))))
        text.append("\n\n".join(parts[2]))
    if 3 in parts:
        text.append(PART3.format(**size))
        text.extend(parts[3])
    with open(doc, "w") as f:
        f.write("\n\n".join(text) + "\n")


PART1 = """## 1. Cost per cell per flux evaluation

Ideal-gas Sod states (tutorials/verification/sodIdealGas, diaphragm across
x) on a 1D tube of {n1D} cells ({steps1D} steps) and on a 3D box of
{n3D}^3 cells ({steps3D} steps), the same meshes and states for every
solver; fixed deltaT = {dt} dx / ({u:g} m/s), no field writes. Time:
difference of the solver's ExecutionTime (CPU time) between the first and
the last step (the first step builds mesh data lazily), the least of
{repeats} interleaved repetitions. A flux evaluation is one MUSCL
reconstruction plus Riemann solve on every face and the update of the
conservative and primitive variables; SSPRK3 does 3 per step,
rhoCentralFoam (Kurganov-Tadmor central-upwind, vanLeer, Euler) 1.
"ratio per eval" is ours per evaluation over rhoCentralFoam per step
(target <= 0.3, issue 18); "ratio per step" compares whole steps (target
<= 1.0); peak RSS per cell includes the libraries and start-up (about
60 MB), so it overstates the marginal memory of a cell on small meshes."""

PROFILE = """Where the time of rhoRiemannFoam goes (HLLC, MUSCL, SSPRK3, the 3D
box of {n3D}^3 cells, whole run including start-up; perf record -e
cpu-clock): libriemannFluxes is the reconstruction (MUSCLReconstruction:
one cell gradient per variable, both face states in one face loop) and the
Riemann solver, librhoEThermo the equation of state on the face states,
libfiniteVolume OpenFOAM's field operations (surface integrals, boundary
conditions), rhoRiemannFoam the conservative update."""

PART2 = """## 2. Speed against error: 50 MPa water shock tube

tutorials/verification/waterShock50MPa (Mie-Grueneisen water, maxCo 0.5,
end time 15 ns) on {meshes} cells, every combination of Riemann solver
(HLLC, HLL, rusanov), limiter of the MUSCL reconstruction of rho, U, p
(MUSCL = monotonized central, vanLeer, upwind = first order) and SSP
Runge-Kutta scheme (SSPRK3, SSPRK2). L1 = volume-weighted mean of
|numerical - exact| at the end time (riemannError). CPU = the solver's
process' CPU time (user + system, from wait4), including its start-up
(about 0.05 s, which dominates the coarse meshes); wall = the solver
process' wall time. Sorted by L1(p)
on the finest mesh."""

PART3 = """## 3. One rank against two ranks

Ideal-gas Sod states along x in a 3D box of {nPar}^3 cells, HLLC, MUSCL,
SSPRK3, fixed deltaT, {stepsPar} steps; decomposePar method simple (2 1 1),
`mpirun -np 2 --bind-to none rhoRiemannFoam -parallel`, the serial run
first, back to back, then the same pair with the stock rhoCentralFoam on
the same mesh as a control of what the shared machine allows at the time;
the least wall time of {repeats} interleaved repetitions. Wall time of the time loop from the arrival of the
first to the last step's ExecutionTime line (the first step excluded);
parallel efficiency = speed-up / ranks (target >= 80 %). Peak RSS: maximum
resident memory of each rank (/usr/bin/time)."""


if __name__ == "__main__":
    bench.main(main)

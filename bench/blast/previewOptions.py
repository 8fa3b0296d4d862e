#!/usr/bin/python3
"""Blast preview per run option: cost against error (not a test).

The default mesh of tutorials/blast/axisymmetricPreview (fluid 0.25 um at
the cell, 0.25 um along the column, solid 0.5 um), 100 um column, 50 MPa for 5 ns, to
150 ns, run with the options that cut its cost without touching the
resolution at the cell:

  default    the tutorial as committed (since 2026-12-02: -outer 8 x -far,
             maxCo 0.9, coupling tolerance 1e-4)
  outer1/4/8 -outer 1e-6 / 4e-6 / 8e-6: the fluid ring beside the cell's
             box (r from 12.4 to 50 um) graded radially from 1 um to that
             size at r = 50 um (1e-6: uniform); the incident plane wave is
             uniform in r there
  co0.5/0.9  maxCo in system/controlDict
  tol1e-6/1e-4  the coupling tolerance in constant/fsiProperties
  hg0.05/hg0.2  the hourglass viscosity halved / doubled (issue 17 item 5)
  mappedForces/pressure  the interface load (the preview's is pressure
             since 2026-12-03)
and their combinations (--options; "outer1+co0.5+tol1e-6" is the default
before 2026-12-02). Two runs at a time (one core each, --jobs), so that
the ratios are measured side by side on the same machine.

Per option: fluid cells, steps, coupling passes per step, unconverged
steps, CPU of cellBlastFoam (its ExecutionTime) to 90 and 150 ns, peak RSS,
and the Fig. 10 probe peaks over t <= 90 ns (the first passage), the
largest nodal speed of the solid after 110 ns (late-time drift), the
probe's largest |strain_z| and von Mises after 140 ns (at rest: issue 17
item 6), the region interfaces' von Mises maxima, and each difference to
the default.

    bench/blast/previewOptions.py [--out DIR] [--doc FILE] [--jobs 2]
        [--options "default outer1+co0.5+tol1e-6 ..."] [--pulse 5e-9]
        [--reportOnly]

Writes docs/benchmarks/blastPreviewOptions.md (or --doc).
"""
import argparse
import datetime
import importlib.machinery
import importlib.util
import os
import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor

import numpy as np

from neuronFsi import script  # noqa: E402
script.guard()  # an input's error: one line, exit 1 (fix19k: every script)
from neuronFsi import bench
from neuronFsi.solidResults import SolidResults

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", ".."))
_loader = importlib.machinery.SourceFileLoader("blastRun",
                                               os.path.join(HERE, "run.py"))
_spec = importlib.util.spec_from_loader("blastRun", _loader)
B = importlib.util.module_from_spec(_spec)
_loader.exec_module(B)

SIZE = dict(Z=100e-6, endTime=1.5e-7, window=9e-8)
# option -> (Allrun options, {(file, entry): value})
PIECES = {
    "outer1": (["-outer", "1e-6"], {}),
    "outer4": (["-outer", "4e-6"], {}),
    "outer8": (["-outer", "8e-6"], {}),
    "co0.5": ([], {("system/controlDict", "maxCo"): "0.5"}),
    "co0.9": ([], {("system/controlDict", "maxCo"): "0.9"}),
    "tol1e-6": ([], {("constant/fsiProperties", "coupling/tolerance"):
                     "1e-6"}),
    "tol1e-4": ([], {("constant/fsiProperties", "coupling/tolerance"):
                     "1e-4"}),
    # the numerical knobs of issue 17 item 5: the hourglass viscosity
    # halved and doubled, the other interface load
    "hg0.05": ([], {("constant/solidProperties", "hourglassViscosity"):
                    "0.05"}),
    "hg0.2": ([], {("constant/solidProperties", "hourglassViscosity"):
                   "0.2"}),
    "mappedForces": ([], {("constant/fsiProperties", "interface/load"):
                          "mappedForces"}),
    "pressure": ([], {("constant/fsiProperties", "interface/load"):
                      "pressure"}),
}
DEFAULT_OPTIONS = ("default outer1+co0.5+tol1e-6 outer1 co0.5 tol1e-6 "
                   "outer4")


def parts(option):
    """Allrun options and dictionary entries of an option name"""
    extra, entries = [], {}
    if option != "default":
        for p in option.split("+"):
            if p not in PIECES:
                raise SystemExit(f"previewOptions: unknown option piece "
                                 f"{p!r} (valid: {', '.join(PIECES)})")
            extra += PIECES[p][0]
            entries.update(PIECES[p][1])
    return extra, entries


def finished(option, out):
    """True when the option's case in out ran to its end (exit 0 in
    /usr/bin/time's log)"""
    path = os.path.join(out, f"opt_{option}", "axisymmetricPreview",
                        "log.time")
    return os.path.exists(path) and B.timeV(path)[3] == 0


def runOption(option, out, env, pulse, keep=False):
    extra, entries = parts(option)
    name = f"opt_{option}"
    if keep and finished(option, out):
        print(f"{option}: finished in {out}, kept", flush=True)
        return
    c, _, cmd = B.prepare(os.path.join(out, name), "1", SIZE["Z"],
                          SIZE["endTime"], env, extra, pulse)
    for (f, e), v in entries.items():
        # -set: sets or adds (-add leaves an existing entry as it is)
        subprocess.run(["foamDictionary", "-entry", e, "-set", v, f], cwd=c,
                       env=env, check=True, stdout=subprocess.DEVNULL)
        cmd += f"; foamDictionary -entry {e} -set {v} {f}"
    with open(os.path.join(c, "bench.cmd"), "w") as o:
        o.write(cmd + "\n")
    print(f"{option}: running cellBlastFoam in {c} ...", flush=True)
    bench.runTimed(c, ["cellBlastFoam"], env, "log.cellBlastFoam")


def lateSpeed(c):
    """largest nodal speed component of the solid in the writes from
    110 ns on [m/s] (solid/solid.h5; tests/blast/checkLongRun.py's
    drift measure), None without such writes"""
    p = os.path.join(c, "solid", "solid.h5")
    if not os.path.exists(p):
        return None
    with SolidResults(p) as f:
        late = [k for k in f.steps() if f.time(k) >= 110e-9]
        if not late:
            return None
        return max(float(np.abs(f.field(k, "velocity")).max())
                   for k in late)


def parse(option, out):
    r = B.parseLevel("1", out, SIZE, name=f"opt_{option}")
    r["option"] = option
    r["cmd"] = open(os.path.join(r["case"], "bench.cmd")).read().strip()
    r["late"] = lateSpeed(r["case"])
    return r


def report(rows, start, end, commit, dirty, pulse):
    ref = next(r for r in rows if r["option"] == "default")
    L = []
    w = L.append
    w("# Blast preview per run option: cost against error")
    w("")
    w(bench.writtenBy("bench/blast/previewOptions.py", start, commit,
                      dirty=dirty)
      + f", {(end - start).total_seconds():.0f} s in all, runs two at a "
      f"time on the {os.cpu_count()}-core machine (one core each; the CPU "
      "time of cellBlastFoam is the cost to compare). Case "
      "`tutorials/blast/axisymmetricPreview`, default mesh (fluid 0.25 um "
      "at the cell, 0.25 um along the column, solid 0.5 um), 50 MPa for "
      f"{pulse*1e9:g} ns, 100 um column, to 150 ns; probe peaks over "
      "t <= 90 ns (the first passage); differences to `default`.")
    w("")
    w("| option | fluid cells | steps | passes/step (mean / max) | "
      "unconverged | CPU to 90 ns [s] | CPU to 150 ns [s] | CPU / default "
      "| peak RSS [MB] | arrival [ns] | peak p [MPa] | peak von Mises [Pa] "
      "| peak strain [-] | peak strain rate [1/s] | peak 1-ns strain rate"
      " [1/s] | interface von Mises max m-c / c-n [Pa] | largest "
      "difference [%] | largest nodal speed after 110 ns [m/s] | after "
      f"{B.REST*1e9:.0f} ns: max \\|strain_z\\|, max von Mises (of the "
      "peak) |")
    w("|---|---:|---:|---|---:|---:|---:|---:|---:|---|---|---|---|---|"
      "---|---|---:|---:|---|")
    for r in rows:
        d = B.diffs(r, ref)
        cw = f"{r['atWindow'][0]:.1f}" if r["atWindow"] else "-"
        fail = "" if r["rc"] == 0 else \
            f" (FAILED at {r['tLast']*1e9:.2f} ns)"
        w(f"| {r['option']} | {r['cells']} | {r['steps']} | "
          f"{r['itMean']:.2f} / {r['itMax']} | {r['notConverged']} | {cw} | "
          f"{r['cpu']:.1f}{fail} | {r['cpu']/ref['cpu']:.2f} | "
          f"{r['rss']:.0f} | {r['arrival']*1e9:.2f} ({d['arrival']:+.2f}) "
          f"| {r['pMax']/1e6:.2f} ({d['pMax']:+.2f} %) | "
          f"{r['vmMax']:.3f} ({d['vmMax']:+.2f} %) | "
          f"{r['strainMin']:.5f} ({d['strainMin']:+.2f} %) | "
          f"{r['rateMin']:.4g} ({d['rateMin']:+.2f} %) | "
          f"{r['rate1nsMin']:.4g} ({d['rate1nsMin']:+.2f} %) | "
          f"{r['vmMC']:.2f} / {r['vmCN']:.2f} ({d['vmMC']:+.1f} / "
          f"{d['vmCN']:+.1f} %) | {d['max']:.2f} | "
          + ("-" if r["late"] is None else f"{r['late']:.3g}") + " | "
          + ("-" if not r.get("rest") else
             f"{r['rest'][0]:.4f}, {r['rest'][1]:.3f} Pa "
             f"({100*r['rest'][1]/r['vmMax']:.0f} %)") + " |")
    w("")
    w("CPU split of the time loop (cellBlastFoam):")
    w("")
    for r in rows:
        w(f"- {r['option']}: {r['split']}")
    w("")
    w("Commands (in a scratch copy of the tutorial, then `/usr/bin/time -v "
      "cellBlastFoam`):")
    w("")
    for r in rows:
        w(f"- {r['option']}: `{r['cmd']}`")
    w("")
    return L


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", default=os.path.join(HERE, "output",
                                                  "previewOptions"))
    ap.add_argument("--doc", default=os.path.join(
        ROOT, "docs", "benchmarks", "blastPreviewOptions.md"))
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--options", default=DEFAULT_OPTIONS)
    ap.add_argument("--pulse", type=float, default=B.PULSE, help="[s]")
    ap.add_argument("--reportOnly", action="store_true")
    ap.add_argument("--keep", action="store_true",
                    help="do not run again the options whose case in --out "
                    "ran to its end (a study continued)")
    args = bench.parse(ap)
    options = args.options.split()
    if "default" not in options:
        options.insert(0, "default")
    for o in options:
        parts(o)                        # unknown pieces fail before a run
    out = os.path.abspath(args.out)
    os.makedirs(out, exist_ok=True)
    env = bench.foamEnv(ROOT)
    commit = bench.commit(ROOT)
    dirty = bench.uncommitted(ROOT, B.SOURCES)
    start = datetime.datetime.utcnow()
    if not args.reportOnly:
        with ThreadPoolExecutor(max_workers=args.jobs) as ex:
            list(ex.map(lambda o: runOption(o, out, env, args.pulse,
                                            args.keep), options))
    end = datetime.datetime.utcnow()
    rows = [parse(o, out) for o in options]
    lines = report(rows, start, end, commit, dirty, args.pulse)
    bench.writeReport(args.doc, lines)
    if any(r["rc"] != 0 for r in rows):
        sys.exit(1)


if __name__ == "__main__":
    bench.main(main)

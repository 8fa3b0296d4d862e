#!/usr/bin/python3
"""The numerical knobs of the blast preview at its default sizes, per pulse
(issue 17 item 5; not a test).

Each knob variant of tutorials/blast/axisymmetricPreview at the Allrun's
default sizes (G since branch def18, 2026-12-05; x0.7 from 2026-12-04), for
each pulse, to 150 ns (or -endTime among the Allrun options):

  base          the tutorial as committed (hourglassViscosity 0.1,
                shearViscosity 0.2 filtered, interface load pressure)
  hg0.05/hg0.2  constant/solidProperties hourglassViscosity halved /
                doubled (previewOptions.py's pieces)
  sv0.1/sv0.4   the filtered shearViscosity halved / doubled (Allrun
                -shearViscosity)
  mappedForces  constant/fsiProperties interface/load mappedForces, the
                other load src/fsi/interfaceMap offers (previewOptions.py)

A run: `tests/blast/runPreview.sh DIR -pulse P -noPlots -noVTK -noRun
[Allrun options]`, the dictionary entries set with foamDictionary in the
copy, then `cellBlastFoam` (under /usr/bin/time -v) and `planeWave -case
. -check` (the Allrun without -noRun runs the same cellBlastFoam and,
with -noPlots -noVTK, nothing else). The measures, each against base of
the same pulse:

  - the fixed-point probe at the Fig. 10 point, cytoplasm and nucleus
    side (planeWave's solidMeasures.dat): 1-ns peak of von Mises and of
    strain_z, and after 140 ns the largest |strain_z| and von Mises;
  - the interface von Mises maxima (postProcessing/solidInterfaces),
    membrane-cytoplasm and cytoplasm-nucleus: the largest over the
    passage (t <= 80 ns + pulse) and over the rest (t >= 140 ns);
  - the reported interface measure (interfacePatches.dat, when the run
    wrote it): the solver's largest mean of von Mises and of the shear
    traction over a fixed length of interface (membrane-cytoplasm,
    cytoplasm-nucleus, membrane-fluid), over the passage and at rest,
    with its centre and time, and the file's element maxima.

    bench/blast/knobMatrix.py [--out DIR] [--doc FILE] [--jobs 2]
        [--variants "base hg0.05 ..."] [--pulses "5e-9 1e-8 1.5e-8"]
        [--keep] [--reportOnly] [-- ALLRUN OPTIONS]

Writes the tables to --doc (default: the --out folder's knobMatrix.md);
runs --jobs cases at a time (run the script under nice -n 10). The case
folders are named by variant and pulse only: give Allrun options (e.g.
another level's sizes) a --out of their own.
"""
import argparse
import importlib.machinery
import importlib.util
import os
import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor

import numpy as np

from neuronFsi import script  # noqa: E402
script.guard()  # an input's error: one line, exit 1 (fix19k: every script)
from neuronFsi import bench, damageIndicators, logs, planeWave
from neuronFsi.solidResults import SolidResults

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", ".."))
_loader = importlib.machinery.SourceFileLoader(
    "previewOptions", os.path.join(HERE, "previewOptions.py"))
_spec = importlib.util.spec_from_loader("previewOptions", _loader)
P = importlib.util.module_from_spec(_spec)
_loader.exec_module(P)
_loader = importlib.machinery.SourceFileLoader(
    "interfaceTop", os.path.join(HERE, "analysis", "interfaceTop.py"))
_spec = importlib.util.spec_from_loader("interfaceTop", _loader)
T = importlib.util.module_from_spec(_spec)
_loader.exec_module(T)

VARIANTS = {
    "base": ([], {}),
    "hg0.05": P.PIECES["hg0.05"],
    "hg0.2": P.PIECES["hg0.2"],
    "sv0.1": (["-shearViscosity", "0.1"], {}),
    "sv0.4": (["-shearViscosity", "0.4"], {}),
    "mappedForces": P.PIECES["mappedForces"],
}
PULSES = "5e-9 1e-8 1.5e-8"
PASSAGE = 80e-9         # [s] the passage ends at PASSAGE + pulse
REST = 140e-9           # [s] at rest from here (issue 17 item 6)
INTERFACES = ("membrane-cytoplasm", "cytoplasm-nucleus")
# the solver's patch means (interfacePatches.dat)
PATCH_INTERFACES = ("membrane-cytoplasm", "cytoplasm-nucleus",
                    "membrane-fluid")
PATCH = 0.5e-6          # [m] radius of the interface patch means


def caseDir(out, variant, pulse):
    return os.path.join(out, f"{variant}_{pulse*1e9:g}ns",
                        "axisymmetricPreview")


def finished(c):
    p = os.path.join(c, "log.time")
    return (os.path.exists(p) and logs.timeV(p)["status"] == 0
            and os.path.exists(os.path.join(
                c, "postProcessing", "planeWave", "0", "solidMeasures.dat")))


def runCase(variant, pulse, out, env, extra, keep, commit, dirty):
    c = caseDir(out, variant, pulse)
    if keep and finished(c):
        print(f"{variant} {pulse:g} s: finished in {c}, kept", flush=True)
        return
    opts, entries = VARIANTS[variant]
    cmd = ([os.path.join(ROOT, "tests", "blast", "runPreview.sh"),
            os.path.dirname(c), "-pulse", f"{pulse:g}", "-noPlots",
            "-noVTK", "-noRun"] + list(extra) + list(opts))
    res = bench.runLogged(cmd, ROOT, env)
    if res.returncode != 0:
        bench.fail(res, f"{' '.join(cmd)} failed")
    text = " ".join(cmd[1:])
    for (f, e), v in entries.items():
        subprocess.run(["foamDictionary", "-entry", e, "-set", v, f], cwd=c,
                       env=env, check=True, stdout=subprocess.DEVNULL)
        text += f"; foamDictionary -entry {e} -set {v} {f}"
    with open(os.path.join(c, "bench.cmd"), "w") as o:
        o.write("tests/blast/runPreview.sh " + text
                + "; cellBlastFoam; planeWave -case . -check\n")
    bench.stampCommit(c, commit, dirty)
    print(f"{variant} {pulse:g} s: cellBlastFoam in {c} ...", flush=True)
    bench.runTimed(c, ["cellBlastFoam"], env, "log.cellBlastFoam")
    with open(os.path.join(c, "log.planeWave"), "w") as o:
        subprocess.run(["planeWave", "-case", ".", "-check"], cwd=c, env=env,
                       stdout=o, stderr=subprocess.STDOUT)
    print(f"{variant} {pulse:g} s: done", flush=True)


def solidRows(c):
    """{region: row} of the Fig. 10 point's probes in solidMeasures.dat
    (the first probe of each region above z = 4 um), each row the floats
    vM vMref errVM strain strainRef errStrain restStrain restVM"""
    path = os.path.join(c, "postProcessing", "planeWave", "0",
                        "solidMeasures.dat")
    out = {}
    for r in planeWave.readMeasures(path):
        if r["z"] > 4e-6 and r["region"] not in out:
            out[r["region"]] = list(r.values())[3:11]
    return out


def measures(c, pulse):
    """The measures of a finished case (see the module's text)"""
    s = solidRows(c)
    m = {}
    for side in ("cytoplasm", "nucleus"):
        r = s[side]
        m[f"vm1ns:{side}"] = r[0]
        m[f"strain1ns:{side}"] = r[3]
        m[f"restStrain:{side}"] = r[6]
        m[f"restVM:{side}"] = r[7]
    im = damageIndicators.interfaceMaxima(c)
    for name in INTERFACES:
        t, _, vm = im[name]
        m[f"ifPassage:{name}"] = vm[t <= PASSAGE + pulse].max()
        late = t >= REST
        # a run ended before REST (-endTime): no rest value
        m[f"ifRest:{name}"] = vm[late].max() if late.any() else np.nan
        # when the passage maximum was reached [s]
        k = np.argmax(np.where(t <= PASSAGE + pulse, vm, -1))
        m[f"ifPassageTime:{name}"] = t[k]
    # the solver's means over a fixed length of interface (interfacePatches
    # .dat, every step): the largest over the passage and at rest, where
    # the von Mises one was reached
    m["patchLength"] = np.nan
    if damageIndicators.hasInterfacePatches(c):
        m["patchLength"] = damageIndicators.patchLength(c)
        ip = damageIndicators.interfacePatches(c)
        for name in PATCH_INTERFACES:
            if name not in ip:
                continue
            d = ip[name]
            t = d["t"]
            w = t <= PASSAGE + pulse
            late = t >= REST
            for q in ("vonMisesPatch", "shearPatch", "pPatch",
                      "vonMisesMax", "shearMax"):
                m[f"{q}:{name}"] = d[q][w].max()
                m[f"{q}Rest:{name}"] = (d[q][late].max() if late.any()
                                        else np.nan)
            k = np.argmax(np.where(w, d["vonMisesPatch"], -np.inf))
            m[f"vonMisesPatchTime:{name}"] = t[k]
            m[f"vonMisesPatchAt:{name}"] = (d["vonMisesPatchX"][k],
                                            d["vonMisesPatchY"][k])
    # the write nearest each interface's passage maximum: the largest
    # element von Mises there and the largest mean over PATCH of interface
    # (interfaceTop.patchMaximum)
    with SolidResults(os.path.join(c, "solid", "solid.h5")) as f:
        X = f.mesh("coordinates")
        conn = f.mesh("connectivity")
        reg = f.mesh("region").ravel()
        C = X[conn].mean(axis=1)
        for name in INTERFACES:
            a, b = name.split("-")
            els = T.band(conn, reg, a, b)
            k = f.nearest(m[f"ifPassageTime:{name}"])
            vm = f.field(k, "vonMises").ravel()
            m[f"writeTime:{name}"] = f.time(k)
            m[f"writeMax:{name}"] = vm[els].max()
            m[f"patchMax:{name}"], e = T.patchMaximum(C, reg, els, vm,
                                                      PATCH)
    # the last write (150 ns): the mean of each side's band elements and
    # the element of the largest von Mises (interfaceTop.py)
    with SolidResults(os.path.join(c, "solid", "solid.h5")) as f:
        X = f.mesh("coordinates")
        conn = f.mesh("connectivity")
        reg = f.mesh("region").ravel()
        vm = f.field(f.steps()[-1], "vonMises").ravel()
    for name in INTERFACES:
        a, b = name.split("-")
        els = T.band(conn, reg, a, b)
        for r in (a, b):
            m[f"bandMean:{name}:{r}"] = vm[els[reg[els] == T.NAMES.index(r)]
                                          ].mean()
        e = els[np.argmax(vm[els])]
        C = X[conn[e]].mean(axis=0)*1e6
        m[f"bandTop:{name}"] = "%s (%.2f, %.2f) um" % (T.NAMES[reg[e]],
                                                       C[0], C[1])
    tv = logs.timeV(os.path.join(c, "log.time"))
    m["cpu"] = tv["user"] + tv["system"]
    m["status"] = tv["status"]
    with open(os.path.join(c, "log.planeWave")) as f:
        m["fails"] = [ln.split(None, 1)[1].strip() for ln in f
                      if ln.startswith("FAIL ")]
    return m


COLUMNS = [
    ("vm1ns:cytoplasm", "von Mises 1-ns peak, cytoplasm side [Pa]", "%.3f"),
    ("vm1ns:nucleus", "nucleus side [Pa]", "%.3f"),
    ("strain1ns:cytoplasm", "strain_z 1-ns peak, cytoplasm side [-]",
     "%.5f"),
    ("strain1ns:nucleus", "nucleus side [-]", "%.5f"),
    ("ifPassage:membrane-cytoplasm",
     "interface von Mises max over the passage, m-c [Pa]", "%.2f"),
    ("ifPassage:cytoplasm-nucleus", "c-n [Pa]", "%.2f"),
]
REST_COLUMNS = [
    ("restStrain:cytoplasm", "\\|strain_z\\| after 140 ns, cytoplasm side "
     "[-]", "%.2e"),
    ("restStrain:nucleus", "nucleus side [-]", "%.2e"),
    ("restVM:cytoplasm", "von Mises after 140 ns, cytoplasm side [Pa]",
     "%.3f"),
    ("restVM:nucleus", "nucleus side [Pa]", "%.3f"),
    ("ifRest:membrane-cytoplasm", "interface von Mises max after 140 ns, "
     "m-c [Pa]", "%.2f"),
    ("ifRest:cytoplasm-nucleus", "c-n [Pa]", "%.2f"),
]


def cell(m, ref, key, fmt, variant):
    x, r = m[key], ref[key]
    # no value (a run ended before 140 ns: planeWave's '-', or nan)
    if not isinstance(x, float) or np.isnan(x):
        return "-"
    v = fmt % x
    if not isinstance(r, float) or np.isnan(r):
        return v
    if variant == "base":
        return v
    d = 100*(x/r - 1)
    bold = "**" if abs(d) >= 5 else ""
    return f"{v} ({bold}{d:+.1f} %{bold})"


def table(rows, columns, w):
    w("| pulse | variant | " + " | ".join(h for _, h, _ in columns)
      + " |")
    w("|---|---|" + "---|"*len(columns))
    for pulse, variant, m, ref in rows:
        w(f"| {pulse*1e9:g} ns | {variant} | "
          + " | ".join(cell(m, ref, k, f, variant) for k, _, f in columns)
          + " |")


def report(results, variants, pulses, extra, cases):
    L = []
    w = L.append
    w("# Numerical knobs of the blast preview (issue 17 item 5)")
    w("")
    commit, dirty = bench.stampedCommit(cases)
    start, end = bench.runPeriod(
        [os.path.join(c, "bench.cmd") for c in cases],
        [os.path.join(c, "log.planeWave") for c in cases])
    w(bench.writtenBy("bench/blast/knobMatrix.py", start, commit,
                      dirty=dirty)
      + f" (the last run ended {end.strftime('%H:%M')} UTC)"
      + ". Allrun options besides the variant's: "
      + (f"`{' '.join(extra)}`" if extra else "none (the defaults)")
      + ". In parentheses: the change against base of the same pulse "
      "(bold: 5 % or more).")
    w("")
    rows = []
    for pulse in pulses:
        ref = results[("base", pulse)]
        for v in variants:
            rows.append((pulse, v, results[(v, pulse)], ref))
    w("Peaks (the probe: planeWave's 1-ns peaks at the Fig. 10 point; "
      f"the interfaces: t <= {PASSAGE*1e9:g} ns + pulse):")
    w("")
    table(rows, COLUMNS, w)
    w("")
    w(f"At rest (t >= {REST*1e9:g} ns to 150 ns):")
    w("")
    table(rows, REST_COLUMNS, w)
    w("")
    if any(not np.isnan(results[(v, p)]["patchLength"])
           for p in pulses for v in variants):
        L_ = next(results[(v, p)]["patchLength"] for p in pulses
                  for v in variants
                  if not np.isnan(results[(v, p)]["patchLength"]))
        cols = [(f"{q}:{n}", f"{lab}, {n} [Pa]", "%.2f")
                for q, lab in (("vonMisesPatch", "von Mises patch mean"),
                               ("shearPatch", "shear patch mean"))
                for n in PATCH_INTERFACES]
        w("The reported interface measure: the solver's largest mean over "
          f"{L_*1e6:g} um of interface (postProcessing/solidInterfaces/"
          "interfacePatches.dat, every step; r-z: an arc of that length), "
          f"largest over the passage (t <= {PASSAGE*1e9:g} ns + pulse):")
        w("")
        table(rows, cols, w)
        w("")
        w("The same at rest (t >= %g ns) and the element maxima of the "
          "same file over the passage (mesh-dependent):" % (REST*1e9))
        w("")
        table(rows, [(f"vonMisesPatchRest:{n}",
                      f"von Mises patch mean at rest, {n} [Pa]", "%.2f")
                     for n in PATCH_INTERFACES]
              + [(f"vonMisesMax:{n}", f"von Mises element max, {n} [Pa]",
                  "%.2f") for n in PATCH_INTERFACES]
              + [(f"shearMax:{n}", f"shear element max, {n} [Pa]", "%.2f")
                 for n in PATCH_INTERFACES], w)
        w("")
        w("Where and when the von Mises patch mean over the passage was "
          "largest (centre r, z [um], time [ns]):")
        w("")
        for pulse, v, m, _ in rows:
            w(f"- {pulse*1e9:g} ns {v}: " + "; ".join(
                "%s (%.2f, %.2f) um at %.2f ns" % (
                    n, 1e6*m[f"vonMisesPatchAt:{n}"][0],
                    1e6*m[f"vonMisesPatchAt:{n}"][1],
                    1e9*m[f"vonMisesPatchTime:{n}"])
                for n in PATCH_INTERFACES
                if f"vonMisesPatchAt:{n}" in m))
        w("")
    w("The interface maxima over elements against means over a length of "
      "the interface, at the write nearest the passage maximum (solid.h5, "
      "every 6.55 ns): the largest element von Mises of the band there, "
      "and the largest mean over the band elements of one region within "
      f"{PATCH*1e6:g} um of a band element (interfaceTop.patchMaximum) "
      "[Pa]:")
    w("")
    w("| pulse | variant | " + " | ".join(
        f"{n}: write [ns] | element max | {PATCH*1e6:g}-um patch max"
        for n in INTERFACES) + " |")
    w("|---|---|" + "---|---|---|"*len(INTERFACES))
    for pulse, v, m, ref in rows:
        w(f"| {pulse*1e9:g} ns | {v} | " + " | ".join(
            "%.2f | %s | %s" % (1e9*m[f"writeTime:{n}"],
                                cell(m, ref, f"writeMax:{n}", "%.2f", v),
                                cell(m, ref, f"patchMax:{n}", "%.2f", v))
            for n in INTERFACES) + " |")
    w("")
    w("Where the interface maxima are at the last write (150 ns): the mean "
      "von Mises of each side's band elements [Pa] and the element of the "
      "largest (region, centroid r, z):")
    w("")
    w("| pulse | variant | " + " | ".join(
        f"{n}: mean, {n.split('-')[0]} side | {n.split('-')[1]} side | "
        "largest at" for n in INTERFACES) + " |")
    w("|---|---|" + "---|---|---|"*len(INTERFACES))
    for pulse, v, m, ref in rows:
        w(f"| {pulse*1e9:g} ns | {v} | " + " | ".join(
            " | ".join(cell(m, ref, f"bandMean:{n}:{r}", "%.2f", v)
                       for r in n.split("-")) + " | " + m[f"bandTop:{n}"]
            for n in INTERFACES) + " |")
    w("")
    w("Per run: cellBlastFoam's CPU (user + system), when the interface "
      "maxima over the passage were reached (m-c / c-n), the bounds "
      "planeWave -check failed:")
    w("")
    for pulse, v, m, _ in rows:
        w(f"- {pulse*1e9:g} ns {v}: {m['cpu']:.1f} s"
          + ("" if m["status"] == 0 else f" (exit {m['status']})")
          + "; " + " / ".join("%.2f ns" % (1e9*m[f"ifPassageTime:{n}"])
                              for n in INTERFACES)
          + "; " + (", ".join(m["fails"]) if m["fails"] else "none"))
    w("")
    return L


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", default=os.path.join(HERE, "output",
                                                  "knobMatrix"))
    ap.add_argument("--doc", default=None)
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--variants", default=" ".join(VARIANTS))
    ap.add_argument("--pulses", default=PULSES)
    ap.add_argument("--keep", action="store_true",
                    help="do not run again the cases in --out that ran to "
                    "their end")
    ap.add_argument("--reportOnly", action="store_true")
    ap.add_argument("extra", nargs="*", help="more Allrun options (after "
                    "--), for every case")
    args = bench.parse(ap)
    variants = args.variants.split()
    for v in variants:
        if v not in VARIANTS:
            sys.exit(f"knobMatrix: unknown variant {v!r} (valid: "
                     f"{', '.join(VARIANTS)})")
    if "base" not in variants:
        variants.insert(0, "base")
    try:
        pulses = [float(p) for p in args.pulses.split()]
    except ValueError:
        pulses = []
    if not pulses or not all(0 < p <= 0.9 for p in pulses):
        sys.exit(f"knobMatrix: --pulses {args.pulses!r}: pulse durations "
                 "[s] in (0, 0.9] (the Allrun's -pulse)")
    out = os.path.abspath(args.out)
    os.makedirs(out, exist_ok=True)
    env = bench.foamEnv(ROOT)
    commit = bench.commit(ROOT)
    dirty = bench.uncommitted(ROOT, ["src", "applications", "tutorials",
                                     "bench/blast"])
    jobs = [(v, p) for p in pulses for v in variants]
    if not args.reportOnly:
        with ThreadPoolExecutor(max_workers=args.jobs) as ex:
            list(ex.map(lambda j: runCase(j[0], j[1], out, env, args.extra,
                                          args.keep, commit, dirty), jobs))
    results = {j: measures(caseDir(out, *j), j[1]) for j in jobs}
    lines = report(results, variants, pulses, args.extra,
                   [caseDir(out, *j) for j in jobs])
    bench.writeReport(args.doc or os.path.join(out, "knobMatrix.md"), lines)


if __name__ == "__main__":
    bench.main(main)

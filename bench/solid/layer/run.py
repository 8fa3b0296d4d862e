#!/usr/bin/python3
"""Layer indentation force: ours, CalculiX and FEniCS (not a test).

Issue 20 item 5. A rigid frictionless sphere (R = 22.5 um) is pressed to
0.1, 1 and 1.5 um into a bonded neo-Hookean layer (radius 25 um, thickness
7.9 um, mu = 13.33 Pa; bottom bonded, side free, axisymmetric). Three codes:

  - ours: bench/solid/layer/layerIndent.C (libsolid: Q1/P0 quads, node-to-
    analytical-sphere augmented Lagrangian, penetration <= 1e-5 um), exactly
    incompressible (d0 = 0) and at K = 1e3 mu (the CalculiX material);
  - CalculiX 2.20 (Debian calculix-ccx): CAX8R on the same corner nodes,
    sphere a stiff CAX8 cap, linear penalty contact 1e5 Pa/um, K = 1e3 mu
    (no exactly incompressible element), the input of
    bench/solid/calculix/hertzMesh.py;
  - FEniCS legacy (dolfin 2019, Debian python3-dolfin, fenicsLayer.py):
    Taylor-Hood P2/P1, exactly incompressible and K = 1e3 mu, penalty
    contact at k and 4k extrapolated to k = inf (error O(1/k)), levels of
    uniform refinement of the same graded map (layerMesh.py) extrapolated
    by Richardson with the observed order: the reference.

Every case runs once in --out (default bench/solid/layer/output, ignored by
git) and is reused when its input (mesh, command) is unchanged: an
interrupted run continues where it stopped. Cost on the project machine
(2 cores shared with other jobs, load 6-9 during the runs of
docs/benchmarks/solidLayerContact.md): about 2 h 30 min wall in all,
CalculiX at n = 80 alone 48 min (545 s CPU), each FEniCS level-2 run about
13 min, each level-3 run (0.1 um only) about 10 min, level 4 (0.1 um only)
about 16-18 min, ours at 160 x 64
exactly incompressible 11 min; --quick (the two coarsest meshes of each
code, the 0.1 um ladder to level 2) some minutes.

FEniCS is not a dependency of the project: if /usr/bin/python3 has no
dolfin, install it for this bench only with 'apt-get install
python3-dolfin'.

Writes docs/benchmarks/solidLayerContact.md (or into --out with --quick).
"""
import datetime
import json
import os
import re
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", "..", ".."))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "..", "calculix"))
import hertzMesh  # noqa: E402
import layerMesh  # noqa: E402
try:
    from neuronFsi import script
except ImportError:
    sys.exit("bench/solid/layer/run.py: error: the project's Python package neuronFsi "
             "is not found: source the project's etc/bashrc first")
script.guard()  # an input's error: one line, exit 1 (adv33)
from neuronFsi import bench, convergence  # noqa: E402

LIB = os.path.join(ROOT, "platforms", "linux64GccDPInt32Opt", "lib")
PYTHON = "/usr/bin/python3"

# Problem [um, Pa]; force unit Pa um^2 = 1 pN
W, H, R, MU = 25.0, 7.9, 22.5, 13.33
DEPTHS = [0.1, 1.0, 1.5]
STEP = 0.1                      # largest depth increment [um]
R_FINE, R_CONTACT = 9.0, 12.0   # uniform cells, contact faces [um]
KC = 1e3*MU                     # CalculiX's bulk modulus [Pa]
TOL = 1e-5                      # our largest penetration [um]
SLOPE = 1e5                     # CalculiX penalty [Pa/um]
PENALTY = 1e4                   # FEniCS penalty k (and 4k) [Pa/um]
ASPECT = (5, 2)                 # n : m (radial : vertical cells)

LADDER = {"full": dict(ours=[20, 40, 80, 160], ccx=[20, 40, 80],
                       fenics=[0, 1, 2], fenicsK=[0, 1], shallow=[3, 4],
                       bulk=[1e2, 1e4], bulkN=80, slopes=[1e4, 3e4]),
          "quick": dict(ours=[20, 40], ccx=[20], fenics=[0, 1],
                        fenicsK=[0, 1], shallow=[2], bulk=[1e2], bulkN=40,
                        slopes=[1e4])}
ENV = dict(os.environ, OMP_NUM_THREADS="1", CCX_NPROC_STIFFNESS="1",
           CCX_NPROC_EQUATION_SOLVER="1", OPENBLAS_NUM_THREADS="1")


def m(n):
    return n*ASPECT[1]//ASPECT[0]


def cached(case, name, content):
    """True if case/name holds content (an unchanged input); else write it
    and remove the results of an older input."""
    os.makedirs(case, exist_ok=True)
    path = os.path.join(case, name)
    if os.path.exists(path) and open(path).read() == content:
        return True
    for f in os.listdir(case):
        os.remove(os.path.join(case, f))
    with open(path, "w") as f:
        f.write(content)
    return False


def run(cmd, case, log):
    res = subprocess.run(cmd, cwd=case, env=ENV, stdout=subprocess.PIPE,
                         stderr=subprocess.STDOUT, text=True)
    with open(os.path.join(case, log), "w") as f:
        f.write(res.stdout)
    if res.returncode != 0:
        sys.stdout.write(res.stdout[-3000:])
        raise RuntimeError(f"{' '.join(cmd)} failed in {case}")
    return res.stdout


def meshText(n):
    """The gmsh text of the n x m mesh and its parts (layerMesh)."""
    import tempfile
    parts = layerMesh.structured(W, H, R_FINE, R_CONTACT, n, m(n))
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "mesh.msh")
        hertzMesh.writeGmsh(path, *parts)
        return open(path).read(), parts


def build(out):
    exe = os.path.join(out, "layerIndent")
    src = os.path.join(HERE, "layerIndent.C")
    if not os.path.exists(os.path.join(LIB, "libsolid.so")):
        raise RuntimeError(f"no libsolid.so in {LIB}: run ./Allwmake first")
    subprocess.run(["g++", "-O3", "-DNDEBUG", "-std=c++17",
                    "-I" + os.path.join(ROOT, "src", "solid", "lnInclude"),
                    "-I" + os.path.join(ROOT, "src", "eos"),
                    "-I/usr/include/eigen3", src, "-L" + LIB, "-lsolid",
                    "-Wl,-rpath," + LIB, "-o", exe], check=True)
    return exe


def runOurs(exe, out, n, K):
    """Forces [pN] at DEPTHS, unknowns, iterations, seconds."""
    case = os.path.join(out, f"ours-n{n}-K{K:g}")
    text, _ = meshText(n)
    cmd = [exe, "mesh.msh", f"{R*1e-6:.15g}", f"{MU:.15g}", f"{K:.15g}",
           f"{STEP*1e-6:.15g}", f"{TOL*1e-6:.15g}"] + \
        [f"{d*1e-6:.15g}" for d in DEPTHS]
    key = text + "\n" + " ".join(cmd[1:])
    log = os.path.join(case, "log.ours")
    if not (cached(case, "input", key) and os.path.exists(log)):
        with open(os.path.join(case, "mesh.msh"), "w") as f:
            f.write(text)
        run(cmd, case, "log.ours.tmp")
        os.replace(log + ".tmp", log)
    lines = open(log).read().splitlines()
    r = dict(n=n, m=m(n), K=K, force=[], radius=[])
    for line in lines:
        w = line.split()
        if w and w[0] == "depth":
            r["force"].append(float(w[3])*1e12)
            r["radius"].append(float(w[5])*1e6)
        elif len(w) == 2:
            r[w[0]] = float(w[1])
    return r


def runCcx(out, n, slope=SLOPE):
    """CalculiX forces [pN] at DEPTHS (K = KC)."""
    case = os.path.join(out, f"ccx-n{n}-s{slope:g}")
    _, nodes = meshText(n)
    geo = hertzMesh.Geometry(R, DEPTHS[-1], W, H, MU, KC, R_CONTACT)
    import tempfile
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "CAX8R.inp")
        hertzMesh.writeCalculix(path, geo, *nodes, slope,
                                round(DEPTHS[-1]/STEP),
                                printTimes=[d/DEPTHS[-1] for d in DEPTHS])
        text = open(path).read()
    dat = os.path.join(case, "CAX8R.dat")
    done = os.path.join(case, "done")
    if not (cached(case, "CAX8R.inp", text) and os.path.exists(done)):
        run(["/usr/bin/time", "-v", "-o", "ccx.time", "ccx", "-i", "CAX8R"],
            case, "log.ccx")
        open(done, "w").close()
    # RF of the driven sphere nodes at the time points, per 2 degrees
    blocks = re.findall(r"total force \(fx,fy,fz\) for set DRIVE and time\s+"
                        r"(\S+)\s+(\S+)\s+(\S+)", open(dat).read())
    force = [-180*float(fy) for _, _, fy in blocks]
    times = [float(t) for t, _, _ in blocks]
    if len(force) != len(DEPTHS) or any(
            abs(t - d/DEPTHS[-1]) > 1e-6 for t, d in zip(times, DEPTHS)):
        raise RuntimeError(f"{dat}: reactions at {times}, expected the "
                           "time points of the depths")
    its = sum(1 for line in open(os.path.join(case, "CAX8R.cvg"))
              if re.match(r"\s+\d+\s+\d+\s+\d+\s+\d+\s", line))
    wall = cpu = float("nan")
    timeFile = os.path.join(case, "ccx.time")
    for line in (open(timeFile) if os.path.exists(timeFile) else []):
        if "Elapsed (wall clock)" in line:
            t = line.split()[-1].split(":")
            wall = sum(float(x)*60**k for k, x in enumerate(reversed(t)))
        if "User time" in line:
            cpu = float(line.split()[-1])
    neq = int(re.search(r"number of equations\s+(\d+)",
                        open(os.path.join(case, "log.ccx")).read()).group(1))
    return dict(n=n, m=m(n), force=force, its=its, wall=wall, cpu=cpu,
                unknowns=neq, slope=slope)


def runFenics(out, level, K, k, depths=DEPTHS):
    """FEniCS forces [pN] at depths for one level, K (0: incompressible),
    penalty k."""
    case = os.path.join(out, f"fenics-L{level}-K{K:g}-k{k:g}"
                        + ("" if depths == DEPTHS else
                           "-d" + "-".join(f"{d:g}" for d in depths)))
    script = os.path.join(HERE, "fenicsLayer.py")
    cmd = [PYTHON, script, "--level", str(level), "--K", f"{K:.15g}",
           "--penalty", f"{k:.15g}", "--W", f"{W}", "--H", f"{H}",
           "--R", f"{R}", "--mu", f"{MU}", "--rFine", f"{R_FINE}",
           "--n0", str(20), "--m0", str(m(20)), "--step", f"{STEP}",
           "--depths"] + [f"{d}" for d in depths]
    key = (" ".join(cmd[2:]) + "\n" + open(script).read()
           + open(os.path.join(HERE, "layerMesh.py")).read())
    res = os.path.join(case, "result.json")
    if not (cached(case, "input", key) and os.path.exists(res)):
        text = run(cmd, case, "log.fenics")
        rows = [json.loads(line) for line in text.splitlines()
                if line.startswith("{")]
        with open(res, "w") as f:
            json.dump(rows, f)
    rows = json.load(open(res))
    return dict(level=level, n=rows[0]["n"], m=rows[0]["m"],
                dofs=rows[0]["dofs"], K=K, k=k,
                force=[r["force"] for r in rows],
                reaction=[r["reaction"] for r in rows],
                pen=[r["maxPenetration"] for r in rows],
                radius=[r["contactRadius"] for r in rows],
                seconds=rows[-1]["seconds"])


def fenicsLadder(out, levels, K, depths=DEPTHS):
    """Per level: forces at k and 4k and their extrapolation to k = inf."""
    rows = []
    for L in levels:
        a = runFenics(out, L, K, PENALTY, depths)
        b = runFenics(out, L, K, 4*PENALTY, depths)
        inf = [fb + (fb - fa)/3 for fa, fb in zip(a["force"], b["force"])]
        rows.append(dict(level=L, n=a["n"], m=a["m"], dofs=a["dofs"], a=a,
                         b=b, force=inf))
        print(f"FEniCS level {L} K {K:g}: " + ", ".join(
            f"{f:.3f}" for f in inf) + " pN", flush=True)
    return rows


def richardson(f0, f1, f2):
    """Observed order p (refinement 2) and the extrapolated value from the
    last three of a ladder (neuronFsi.convergence.threeLevel, h = 4, 2, 1);
    p nan and the finest value when the changes are not monotone."""
    c = convergence.threeLevel((4, 2, 1), (f0, f1, f2))
    if c.kind != "monotone":
        return float("nan"), f2
    return c.p, c.extrapolated


def pct(a, b):
    return 100*(a/b - 1)


def main():
    ap = bench.arguments(__doc__, os.path.join(HERE, "output"),
                         "the two coarsest meshes of each code, output in "
                         "--out")
    ap.add_argument("--part", choices=["all", "ours", "fenics", "shallow",
                                       "ccx"],
                    default="all", help="run only this code's cases (to "
                    "run the codes side by side into one --out); the "
                    "report needs all")
    args = bench.parse(ap)
    size = "quick" if args.quick else "full"
    lad = LADDER[size]
    out = os.path.abspath(args.out)
    doc = bench.reportPath(args.doc, args.quick, out, ROOT,
                           "solidLayerContact.md")
    os.makedirs(out, exist_ok=True)
    if args.part in ("all", "fenics", "shallow") and subprocess.run(
            [PYTHON, "-c", "import dolfin"], stdout=subprocess.DEVNULL,
            stderr=subprocess.DEVNULL).returncode != 0:
        sys.exit("run.py: no dolfin for /usr/bin/python3: install FEniCS "
                 "legacy for this bench with 'apt-get install "
                 "python3-dolfin' (not a project dependency)")
    start = datetime.datetime.utcnow()
    part = args.part
    if part in ("all", "fenics"):
        fen = fenicsLadder(out, lad["fenics"], 0.0)
        fenK = fenicsLadder(out, lad["fenicsK"], KC)
    if part in ("all", "shallow"):
        shallow = fenicsLadder(out, lad["shallow"], 0.0, DEPTHS[:1])
    if part in ("all", "ours"):
        exe = build(out)
        ours = {K: [runOurs(exe, out, n, K) for n in lad["ours"]]
                for K in (0.0, KC)}
        for K in (0.0, KC):
            for r in ours[K]:
                print(f"ours n {r['n']} K {K:g}: " + ", ".join(
                    f"{f:.3f}" for f in r["force"]) + " pN", flush=True)
        bulk = [runOurs(exe, out, lad["bulkN"], b*MU) for b in lad["bulk"]]
    if part in ("all", "ccx"):
        ccx = []
        for n in lad["ccx"]:
            ccx.append(runCcx(out, n))
            print(f"CalculiX n {n}: " + ", ".join(
                f"{f:.3f}" for f in ccx[-1]["force"]) + " pN", flush=True)
        slopes = [runCcx(out, lad["ccx"][0], s) for s in lad["slopes"]]
    if part != "all":
        return
    lines = report(size, start, ours, bulk, fen, fenK, shallow, ccx, slopes,
                   lad)
    bench.writeReport(doc, lines)


def extrapolate(rows):
    """Per depth (order, extrapolated force) of a ladder (>= 3 rows), or
    (nan, finest) with fewer."""
    res = []
    for j in range(len(DEPTHS)):
        f = [r["force"][j] for r in rows]
        res.append(richardson(*f[-3:]) if len(f) >= 3
                   else (float("nan"), f[-1]))
    return res


def report(size, start, ours, bulk, fen, fenK, shallow, ccx, slopes, lad):
    L = []
    w = L.append
    ref = extrapolate(fen)
    # 0.1 um: the contact radius (1.6 um) spans few cells on the coarse
    # levels; two more levels loaded to 0.1 um only
    deep = [dict(level=r["level"], n=r["n"], m=r["m"], dofs=r["dofs"],
                 a=r["a"]["force"][0], b=r["b"]["force"][0],
                 f=r["force"][0], pen=r["b"]["pen"][0],
                 radius=r["b"]["radius"][0]) for r in fen + shallow]
    ref0 = list(ref)
    ref[0] = richardson(*[x["f"] for x in deep[-3:]])
    # Uncertainty of the reference [%]: the larger of the finest level's
    # distance to it and the finest level's last change
    ladders = [[x["f"] for x in deep]] + [[r["force"][j] for r in fen]
                                          for j in range(1, len(DEPTHS))]
    refUnc = [max(abs(pct(f[-1], x[1])), abs(pct(f[-1], f[-2])))
              for f, x in zip(ladders, ref)]
    # K = 1e3 mu: the incompressible reference times the compressibility
    # ratio F(K)/F(inf) of the finest level run at both (the ratio
    # converges much faster than the forces)
    comp = [(r["level"], [a/b for a, b in zip(r["force"], next(
        x for x in fen if x["level"] == r["level"])["force"])])
        for r in fenK]
    refK = [(float("nan"), x[1]*q) for x, q in zip(ref, comp[-1][1])]
    elapsed = (datetime.datetime.utcnow() - start).total_seconds()
    dcols = " | ".join(f"F({d:g} um) [pN]" for d in DEPTHS)
    dalign = "|".join("---:" for _ in DEPTHS)
    w("# Solid benchmark: indentation of a bonded incompressible layer, "
      "ours against CalculiX and FEniCS")
    w("")
    paths = ["src/solid", "bench/solid/layer", "bench/solid/calculix"]
    dirty = bench.uncommitted(ROOT, paths)
    w(bench.writtenBy("bench/solid/layer/run.py", start,
                      bench.commit(ROOT), size, dirty, ", ".join(paths))
      + f", {elapsed:.0f} s (cases already in --out reused); 2 cores "
      "shared with other jobs.")
    w("")
    w("Command: `bench/solid/layer/run.py` (FEniCS: `apt-get install "
      "python3-dolfin`, for this bench only).")
    w("")
    w("## Case")
    w("")
    w(f"Rigid frictionless sphere R = {R} um pressed to "
      + ", ".join(f"{d:g}" for d in DEPTHS)
      + f" um (increments <= {STEP} um) into a neo-Hookean layer of radius "
      f"{W} um and thickness {H} um, mu = {MU} Pa, bottom bonded, side "
      "free, axisymmetric. Strain energy mu/2 (I1bar - 3) + K/2 (J - 1)^2 "
      f"(K = inf: exactly incompressible; K = 1e3 mu = {KC:.0f} Pa: the "
      "CalculiX material, NEO HOOKE C10 = mu/2, D1 = 2/K). All meshes are "
      "the graded map of bench/solid/layer/layerMesh.py (cells uniform in "
      f"r <= {R_FINE} um, the contact edge is at "
      f"{fen[-1]['b']['radius'][0]:.1f}-{fen[-1]['b']['radius'][-1]:.1f} um; "
      "cells at the "
      f"top 3x smaller than at the bottom), n x m cells with n:m = "
      f"{ASPECT[0]}:{ASPECT[1]}; ours and CalculiX on the same corner nodes. "
      "mu = 13.33 Pa as issue 20 states it (the tutorials' nucleus has "
      "C10 = 13.33 Pa, mu = 26.66 Pa): at a fixed K/mu every force scales "
      "with mu, so the percentages below hold for either reading.")
    w("")
    w("| | element | contact | incompressibility |")
    w("|---|---|---|---|")
    w(f"| ours (libsolid, layerIndent.C) | Q1/P0 quad | nodes to the "
      f"analytical sphere, augmented Lagrangian, penetration <= {TOL} um | "
      "exact (d0 = 0) or K = 1e3 mu |")
    w(f"| CalculiX 2.20 | CAX8R (midside nodes on the same edges) | surface "
      f"to surface, linear penalty {SLOPE:.0e} Pa/um against a stiff CAX8 "
      "cap | K = 1e3 mu only |")
    w(f"| FEniCS 2019 (fenicsLayer.py) | Taylor-Hood P2/P1 triangles | "
      f"penalty on the reference top surface, k = {PENALTY:.0e} and "
      f"{4*PENALTY:.0e} Pa/um, extrapolated to k = inf | exact "
      "(mixed u-p) or K = 1e3 mu |")
    w("")
    w("## The reference: FEniCS, penalty and mesh convergence")
    w("")
    for rows, rr0, name in ((fen, ref0, "exactly incompressible"),
                            (fenK, None, "K = 1e3 mu")):
        w(f"### FEniCS, {name}")
        w("")
        w("Per level (mesh n x m cells of 2 triangles, dofs of P2/P1): the "
          "force at k, at 4k, and extrapolated to k = inf (F(4k) + "
          "(F(4k) - F(k))/3); 'change': from the level before "
          "(k = inf) [%].")
        w("")
        w("| level | n x m | dofs | depth [um] | F(k) [pN] | F(4k) [pN] | "
          "F(k = inf) [pN] | change [%] | penetration at 4k [um] | "
          "contact radius [um] |")
        w("|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|")
        for i, r in enumerate(rows):
            for j, d in enumerate(DEPTHS):
                ch = (f"{pct(r['force'][j], rows[i - 1]['force'][j]):+.4f}"
                      if i else "-")
                w(f"| {r['level']} | {r['n']} x {r['m']} | {r['dofs']} | "
                  f"{d:g} | {r['a']['force'][j]:.3f} | "
                  f"{r['b']['force'][j]:.3f} | {r['force'][j]:.3f} | {ch} "
                  f"| {r['b']['pen'][j]:.2e} | {r['b']['radius'][j]:.3f} |")
        w("")
        if rows is fenK:
            w("Compressibility F(K = 1e3 mu)/F(inf) - 1 [%] per level "
              "(k = inf); the reference at K = 1e3 mu is the incompressible "
              "reference times the finest level's ratio:")
            w("")
            w("| level | " + " | ".join(f"{d:g} um" for d in DEPTHS) + " |")
            w(f"|---:|{dalign}|")
            for level, q in comp:
                w(f"| {level} | " + " | ".join(f"{100*(x - 1):+.4f}" for x in q)
                  + " |")
            w("")
            continue
        w("Richardson from the three finest levels: observed order p = "
          "log2(d1/d2) of the successive changes d1, d2, F_h->0 = "
          "F_finest + d2/(2^p - 1); 'nan' where the changes alternate in "
          "sign or do not shrink (not in the asymptotic range): there the "
          "finest level is taken and the last change is its uncertainty:")
        w("")
        w("| depth [um] | order p | F extrapolated [pN] | finest level to "
          "extrapolated [%] | last change [%] |")
        w("|---:|---:|---:|---:|---:|")
        for j, d in enumerate(DEPTHS):
            p, fx = rr0[j]
            w(f"| {d:g} | {p:.2f} | {fx:.3f} | "
              f"{pct(rows[-1]['force'][j], fx):+.4f} | "
              f"{pct(rows[-1]['force'][j], rows[-2]['force'][j]):+.4f} |")
        w("")
        if rows is not fen:
            continue
        w(f"At {DEPTHS[0]:g} um the coarse levels are not in the asymptotic "
          "range (the contact radius spans few cells); levels "
          + ", ".join(str(r["level"]) for r in shallow) + " loaded to "
          f"{DEPTHS[0]:g} um only:")
        w("")
        w("| level | n x m | dofs | F(k) [pN] | F(4k) [pN] | F(k = inf) "
          "[pN] | change [%] | penetration at 4k [um] | contact radius "
          "[um] |")
        w("|---:|---|---:|---:|---:|---:|---:|---:|---:|")
        for i, x in enumerate(deep):
            ch = f"{pct(x['f'], deep[i - 1]['f']):+.4f}" if i else "-"
            w(f"| {x['level']} | {x['n']} x {x['m']} | {x['dofs']} | "
              f"{x['a']:.4f} | {x['b']:.4f} | {x['f']:.4f} | {ch} | "
              f"{x['pen']:.2e} | {x['radius']:.3f} |")
        w("")
        w(f"Richardson from levels {deep[-3]['level']}-{deep[-1]['level']}:"
          f" order {ref[0][0]:.2f}, F = {ref[0][1]:.4f} pN (the finest "
          f"level {pct(deep[-1]['f'], ref[0][1]):+.4f} % from it, its last "
          f"change {pct(deep[-1]['f'], deep[-2]['f']):+.4f} %); this is "
          f"the reference at {DEPTHS[0]:g} um below (the levels above "
          f"alone give {ref0[0][1]:.4f} pN).")
        w("")
    w("Equilibrium check: the bottom reaction equals the contact force to "
      "within " + f"{max(abs(pct(r[x]['reaction'][j], r[x]['force'][j])) for r in fen + fenK for x in 'ab' for j in range(len(DEPTHS))):.1e}"
      " % in every FEniCS run.")
    w("")
    w("## Ours and CalculiX against the reference")
    w("")
    w("Error [%] against the reference of the same "
      "material (exactly incompressible: "
      + ", ".join(f"{x[1]:.3f}" for x in ref) + " pN; K = 1e3 mu: "
      + ", ".join(f"{x[1]:.3f}" for x in refK) + " pN at "
      + ", ".join(f"{d:g}" for d in DEPTHS) + " um).")
    w("")
    w(f"| code | K | n x m | unknowns | {dcols} | "
      + " | ".join(f"err {d:g} um [%]" for d in DEPTHS) + " |")
    w(f"|---|---|---|---:|{dalign}|{dalign}|")
    for K, rr in ((0.0, ref), (KC, refK)):
        for r in ours[K]:
            w(f"| ours | {'inf' if K == 0 else '1e3 mu'} | {r['n']} x "
              f"{r['m']} | {int(r['unknowns'])} | "
              + " | ".join(f"{f:.3f}" for f in r["force"]) + " | "
              + " | ".join(f"{pct(f, x[1]):+.3f}"
                           for f, x in zip(r["force"], rr)) + " |")
    for r in ccx:
        w(f"| CalculiX CAX8R | 1e3 mu | {r['n']} x {r['m']} | "
          f"{r['unknowns']} | "
          + " | ".join(f"{f:.3f}" for f in r["force"]) + " | "
          + " | ".join(f"{pct(f, x[1]):+.3f}"
                       for f, x in zip(r["force"], refK)) + " |")
    w("")
    w("Same nodes, CalculiX (K = 1e3 mu) against ours at K = 1e3 mu and "
      "against ours exactly incompressible [%]:")
    w("")
    w("| n x m | " + " | ".join(f"vs ours K=1e3mu, {d:g} um" for d in DEPTHS)
      + " | " + " | ".join(f"vs ours K=inf, {d:g} um" for d in DEPTHS)
      + " |")
    w(f"|---|{dalign}|{dalign}|")
    for r in ccx:
        oK = next(o for o in ours[KC] if o["n"] == r["n"])
        o0 = next(o for o in ours[0.0] if o["n"] == r["n"])
        w(f"| {r['n']} x {r['m']} | "
          + " | ".join(f"{pct(f, g):+.3f}" for f, g in
                       zip(r["force"], oK["force"])) + " | "
          + " | ".join(f"{pct(f, g):+.3f}" for f, g in
                       zip(r["force"], o0["force"])) + " |")
    w("")
    w(f"CalculiX penalty: the {lad['ccx'][0]} x {m(lad['ccx'][0])} mesh at "
      "other slopes of the pressure-overclosure law, force against the "
      f"slope {SLOPE:.0e} Pa/um [%]:")
    w("")
    w("| slope [Pa/um] | " + " | ".join(f"{d:g} um" for d in DEPTHS)
      + " |")
    w(f"|---:|{dalign}|")
    for r in slopes:
        w(f"| {r['slope']:.0e} | " + " | ".join(
            f"{pct(f, g):+.3f}" for f, g in zip(r["force"], ccx[0]["force"]))
          + " |")
    w("")
    w("## Compressibility and finite strain")
    w("")
    w(f"Ours on the {lad['bulkN']} x {m(lad['bulkN'])} mesh, force at "
      "finite K against exactly incompressible [%], and FEniCS at "
      "K = 1e3 mu against incompressible (finest level run at both, "
      "k = inf):")
    w("")
    w("| K/mu | " + " | ".join(f"{d:g} um" for d in DEPTHS) + " |")
    w(f"|---:|{dalign}|")
    o0 = next(o for o in ours[0.0] if o["n"] == lad["bulkN"])
    oK = next(o for o in ours[KC] if o["n"] == lad["bulkN"])
    for b, r in sorted([(x, r) for x, r in zip(lad["bulk"], bulk)]
                       + [(1e3, oK)], key=lambda t: t[0]):
        w(f"| {b:.0e} (ours) | " + " | ".join(
            f"{pct(f, g):+.3f}" for f, g in zip(r["force"], o0["force"]))
          + " |")
    w(f"| 1e+03 (FEniCS level {comp[-1][0]}) | " + " | ".join(
        f"{100*(q - 1):+.3f}" for q in comp[-1][1]) + " |")
    w("")
    w("CalculiX switches geometric nonlinearity on by itself for "
      "*HYPERELASTIC materials (its log: 'reading *HYPERELASTIC: nonlinear "
      "geometric'), so a CalculiX run without NLGEOM is still a finite-"
      "strain run; a small-strain comparison cannot arise that way.")
    w("")
    soft = next(r for r in bulk if abs(r["K"]/MU - 1e2) < 1e-6)
    w("Growth with depth: the compressibility effect grows from "
      f"{DEPTHS[0]:g} to {DEPTHS[-1]:g} um as the contact radius a "
      "approaches the thickness H (a bonded layer confines the material "
      "under the indenter more as a/H grows, the usual thin-layer "
      "behaviour). It is not a finite-strain difference between the codes: "
      "all three solve the finite-strain problem and agree when given the "
      "same K. a: FEniCS finest level at 4k; compressibility from the "
      "tables above:")
    w("")
    w("| depth [um] | d/H | a [um] | a/H | K = 1e3 mu [%] | K = 1e2 mu "
      "(ours) [%] |")
    w("|---:|---:|---:|---:|---:|---:|")
    for j, d in enumerate(DEPTHS):
        a = fen[-1]["b"]["radius"][j]
        w(f"| {d:g} | {d/H:.3f} | {a:.2f} | {a/H:.2f} | "
          f"{100*(comp[-1][1][j] - 1):+.3f} | "
          f"{pct(soft['force'][j], o0['force'][j]):+.3f} |")
    w("")
    verdict(w, ours, bulk, fen, fenK, ccx, slopes, lad, ref, refK, comp,
            refUnc)
    return L


def verdict(w, ours, bulk, fen, fenK, ccx, slopes, lad, ref, refK, comp,
            refUnc):
    """The answer to issue 20 item 5, from the numbers above."""
    js = range(len(DEPTHS))
    at = ", ".join(f"{d:g}" for d in DEPTHS) + " um"
    lst = lambda xs, f="{:+.2f}": "/".join(f.format(x) for x in xs)
    o0, oK, c = ours[0.0][-1], ours[KC][-1], ccx[-1]
    oKc = next(o for o in ours[KC] if o["n"] == c["n"])
    o0c = next(o for o in ours[0.0] if o["n"] == c["n"])
    oB = next(o for o in ours[0.0] if o["n"] == lad["bulkN"])
    soft = next(r for r in bulk if abs(r["K"]/MU - 1e2) < 1e-6)
    penDiff = [pct(fen[-1]["force"][j], fen[-1]["b"]["force"][j])
               for j in js]
    comp = [100*(q - 1) for q in comp[-1][1]]
    errO = [pct(o0["force"][j], ref[j][1]) for j in js]
    errC = [pct(c["force"][j], refK[j][1]) for j in js]
    errOK = [pct(oK["force"][j], refK[j][1]) for j in js]
    w("## Verdict")
    w("")
    w(f"- **Answer: both codes are right, and the +2 % is not "
      f"reproduced.** Against the converged FEniCS reference of the same "
      f"material, ours ({o0['n']} x {o0['m']}) is within "
      f"{max(map(abs, errO + errOK)):.2f} % and CalculiX ({c['n']} x "
      f"{c['m']}) within {max(map(abs, errC)):.2f} % at every depth; the "
      f"reference itself is uncertain by {lst(refUnc, '{:.2f}')} % at "
      f"{at}. Nothing in src/solid needs fixing.")
    w(f"- **Reference** (FEniCS Taylor-Hood, exactly incompressible, "
      f"penalty and mesh extrapolated): {lst([x[1] for x in ref], '{:.3f}')}"
      f" pN at {at}, uncertain by {lst(refUnc, '{:.3f}')} % (the larger of "
      "the finest level's distance to it and its last change). Penalty: "
      "k -> inf moves the finest level's force by "
      f"{lst(penDiff, '{:+.3f}')} % from 4k; mesh: the Richardson tables "
      "above; equilibrium: the bottom reaction equals the contact force.")
    w(f"- **Ours** (exactly incompressible, {o0['n']} x {o0['m']}): "
      f"{lst(errO, '{:+.3f}')} % from the reference at {at} (its own "
      f"last change, from {ours[0.0][-2]['n']} x {ours[0.0][-2]['m']}: "
      f"{lst([pct(o0['force'][j], ours[0.0][-2]['force'][j]) for j in js], '{:+.3f}')}"
      " %); at "
      f"K = 1e3 mu {lst([pct(oK['force'][j], refK[j][1]) for j in js], '{:+.3f}')}"
      " % from the reference at that K.")
    w(f"- **CalculiX** (CAX8R, K = 1e3 mu, {c['n']} x {c['m']}): "
      f"{lst(errC, '{:+.3f}')} % from the reference at its K, "
      f"{lst([pct(c['force'][j], ref[j][1]) for j in js], '{:+.3f}')} % "
      "from the incompressible reference. Its finite bulk modulus accounts "
      f"for {lst(comp, '{:+.3f}')} % (FEniCS level {fenK[-1]['level']}, "
      "K = 1e3 mu against exactly incompressible), the rest is its mesh, "
      "penalty and Newton tolerance (CalculiX's default, 0.5 % of the mean "
      "force).")
    w(f"- **Same nodes** ({c['n']} x {c['m']}): ours exactly "
      "incompressible over CalculiX is "
      f"{lst([pct(o0c['force'][j], c['force'][j]) for j in js])} %, ours at "
      "CalculiX's K over CalculiX "
      f"{lst([pct(oKc['force'][j], c['force'][j]) for j in js])} % at {at}.")
    w(f"- **The issue's +2 % at 1 um (+0.3 % at 0.1, about +3 % at 1.5 um) "
      "is not reproduced** with the same material on converged meshes. "
      "Compressibility at K = 1e3 mu is "
      f"{lst(comp)} %, and finite strain is in all three codes (CalculiX's "
      "NLGEOM is forced on by the hyperelastic material). A gap of the "
      "claimed size at 1 and 1.5 um is what a ten times more compressible "
      f"CalculiX material gives (ours at K = 1e2 mu, {oB['n']} x "
      f"{oB['m']}: {lst([pct(soft['force'][j], oB['force'][j]) for j in js])}"
      f" % against incompressible), not the +0.3 % at 0.1 um; a ten times "
      f"softer CalculiX penalty ({slopes[0]['slope']:.0e} Pa/um, "
      f"{ccx[0]['n']} x {ccx[0]['m']}) gives only "
      f"{lst([pct(slopes[0]['force'][j], ccx[0]['force'][j]) for j in js])}"
      " %. The outside check's inputs are not in the repository, so its "
      "cause cannot be told.")
    w("")


if __name__ == "__main__":
    bench.main(main)

#!/usr/bin/python3
"""Indentation protocol per mesh: cost against error (not a test).

Runs tutorials/indentation/meshConvergence.sh (the full multi-rate protocol
of the paper's Table 1 on the averageCell tutorial, cellMesh sizes scaled by
a factor) for each mesh, one after the other, and tabulates per mesh the
elements, the peak forces, Newton iterations, wall and CPU time of
cellIndentationFoam and its peak resident memory (/usr/bin/time), with the
difference of each peak to the finest mesh (speed against error).

    bench/indentation/run.py [--quick] [--out DIR] [--doc FILE]

Full: size factors 1.4 1 0.7 0.5 (about 4 min CPU); --quick: 1.4 and 1
(about 1 min CPU), written into --out. The case, its parameter set and
geometry are whatever is committed in tutorials/indentation/averageCell.
Writes docs/benchmarks/indentation.md and indentation_cost_vs_error.png.
"""
import datetime
import os
import subprocess
import sys

try:
    from neuronFsi import script
except ImportError:
    sys.exit("bench/indentation/run.py: error: the project's Python package neuronFsi "
             "is not found: source the project's etc/bashrc first")
script.guard()  # an input's error: one line, exit 1 (adv33)
from neuronFsi import bench

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", ".."))
FACTORS = {"full": ["1.4", "1", "0.7", "0.5"], "quick": ["1.4", "1"]}
PEAKS = ["F_B", "C1,i", "C1,ii", "C1,iii", "C2,i", "C2,ii", "C2,iii",
         "C3,i", "C3,ii", "C3,iii", "F_E"]


def run(factors, work, case):
    env = dict(os.environ, WORK=work, CASE=case)
    rows = []
    for f in factors:
        res = subprocess.run([os.path.join(ROOT, "tutorials", "indentation",
                                           "meshConvergence.sh"), f],
                             env=env, stdout=subprocess.PIPE, text=True)
        if res.returncode != 0:
            sys.stdout.write(res.stdout)
            raise bench.BenchError(f"meshConvergence.sh {f} failed (in "
                                   f"{work}; its output is above)")
        line = [x.strip() for x in res.stdout.strip().splitlines()[-1]
                .strip("|").split("|")]
        # factor, elements, delta0, 11 forces, iterations, wall, CPU, MB
        r = dict(factor=line[0], elements=int(line[1]),
                 delta0=float(line[2]),
                 forces=[float(x) for x in line[3:14]],
                 its=int(line[14]), wall=float(line[15]),
                 cpu=float(line[16]), mb=float(line[17]))
        rows.append(r)
        print(f"factor {f}: {r['elements']} elements, C1,i "
              f"{r['forces'][1]:.3f} nN, CPU {r['cpu']:.1f} s, "
              f"{r['mb']:.0f} MB", flush=True)
    return rows


def maxDiff(r, ref):
    """Largest |F/F_ref - 1| over the nine peaks [%]."""
    return max(100*abs(a/b - 1) for a, b in zip(r["forces"][1:10],
                                                  ref["forces"][1:10]))


def plot(rows, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    ref = rows[-1]
    fig, ax = plt.subplots(figsize=(6.4, 4.4))
    pts = [(r["cpu"], maxDiff(r, ref), r) for r in rows[:-1]]
    ax.loglog([p[0] for p in pts], [p[1] for p in pts], "o-",
              label="max over the nine peaks")
    c1 = [(r["cpu"], 100*abs(r["forces"][1]/ref["forces"][1] - 1))
          for r in rows[:-1]]
    ax.loglog([p[0] for p in c1], [max(p[1], 1e-3) for p in c1], "s--",
              label="C1,i")
    for t, e, r in pts:
        ax.annotate(f"{r['elements']} el.", (t, e), fontsize=7,
                    xytext=(3, 3), textcoords="offset points")
    ax.set_xlabel("CPU time of cellIndentationFoam [s]")
    ax.set_ylabel(f"|F - F_finest|/F_finest [%] "
                  f"(finest: {ref['elements']} el.)")
    ax.set_title("Indentation protocol, averageCell: peak-force "
                 "difference vs cost")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=120)


def report(rows, size, start, case):
    elapsed = (datetime.datetime.now() - start).total_seconds()
    commit = bench.commit(ROOT)
    load = " ".join(f"{x:.2f}" for x in os.getloadavg())
    ref = rows[-1]
    L = []
    w = L.append
    w("# Indentation protocol per mesh: cost against error")
    w("")
    w(bench.writtenBy("bench/indentation/run.py", start, commit, size)
      + f", {elapsed:.0f} s in all; load average "
      f"at the end {load} on {os.cpu_count()} shared cores, so wall times "
      "are noisy: the CPU time of the process is the one-core cost.")
    w("")
    w(f"Case `tutorials/indentation/{case}` as committed (its parameter "
      "set, geometry and 0.1 um depth steps), the full protocol of the "
      "paper's Table 1, through `tutorials/indentation/meshConvergence.sh` "
      "(cellMesh sizes scaled by the factor). Forces in nN: F_B at the end "
      "of the hold B, the nine peaks, F_E at the end of E. Peak memory: "
      "maximum resident set of cellIndentationFoam (/usr/bin/time).")
    w("")
    w("| size factor | elements | delta0 [um] | " + " | ".join(PEAKS)
      + " | Newton its | wall [s] | CPU [s] | peak RSS [MB] |")
    w("|" + "---:|"*(3 + len(PEAKS) + 4))
    for r in rows:
        w(f"| {r['factor']} | {r['elements']} | {r['delta0']:.3f} | "
          + " | ".join(f"{x:.3f}" for x in r["forces"])
          + f" | {r['its']} | {r['wall']:.1f} | {r['cpu']:.1f} | "
          f"{r['mb']:.0f} |")
    w("")
    w(f"Speed against error: difference to the finest mesh "
      f"({ref['elements']} elements) [%].")
    w("")
    w("| elements | CPU [s] | CPU / finest | C1,i [%] | C2,ii [%] | "
      "C3,iii [%] | F_E [%] | max over the nine peaks [%] |")
    w("|---:|---:|---:|---:|---:|---:|---:|---:|")
    for r in rows:
        d = [100*(a/b - 1) for a, b in zip(r["forces"], ref["forces"])]
        w(f"| {r['elements']} | {r['cpu']:.1f} | "
          f"{r['cpu']/ref['cpu']:.2f} | {d[1]:+.2f} | {d[5]:+.2f} | "
          f"{d[9]:+.2f} | {d[10]:+.2f} | {maxDiff(r, ref):.2f} |")
    w("")
    return L


def main():
    ap = bench.arguments(__doc__, os.path.join(HERE, "output"),
                         "two coarse meshes, output in --out")
    ap.add_argument("--case", default="averageCell")
    args = bench.parse(ap)
    # a case that is not a tutorial: said before any run (adv33 bn07:
    # "RuntimeError: meshConvergence.sh 1.4 failed", a traceback)
    cases = os.path.join(ROOT, "tutorials", "indentation")
    if not os.path.isfile(os.path.join(cases, args.case, "system",
                                       "controlDict")):
        valid = sorted(d for d in os.listdir(cases) if os.path.isfile(
            os.path.join(cases, d, "system", "controlDict")))
        raise bench.BenchError(
            "--case '%s' is not a case of %s (a directory with "
            "system/controlDict); valid: %s. Nothing was run"
            % (args.case, cases, " ".join(valid)))
    size = "quick" if args.quick else "full"
    out = os.path.abspath(args.out)
    doc = bench.reportPath(args.doc, args.quick, out, ROOT,
                           "indentation.md")
    os.makedirs(out, exist_ok=True)
    os.makedirs(os.path.dirname(doc), exist_ok=True)
    start = datetime.datetime.utcnow()
    rows = run(FACTORS[size], out, args.case)
    lines = report(rows, size, start, args.case)
    png = "indentation_cost_vs_error.png"
    plot(rows, os.path.join(os.path.dirname(doc), png))
    lines += [f"![peak-force difference against CPU time]({png})", ""]
    bench.writeReport(doc, lines)


if __name__ == "__main__":
    bench.main(main)

#!/usr/bin/python3
"""Where a blast case's water probes sample (docs/results/blast3D.md,
"Where the water probes sample"); not a test.

    bench/blast/analysis/probePoints.py CASE [--np N] [--out DIR]

CASE: a prepared or finished case of tutorials/blast/quarter3D or
axisymmetricPreview (constant/polyMesh, system/, 0/). In a scratch copy
(constant, system, 0; the case is not written to) the cell centres are
written at time 0 (postProcess writeCellCentres) and the linear fields
Cx, Cy, Cz are sampled at every location of the probes function object
fluidProbes, by OpenFOAM's probes with cellPoint ("probes"), by
movingMeshProbes with the case's own scheme, cellPoint ("cellPoint"), and
with cellLinearFit ("fit"). A scheme that interpolates at the probe's
point reads the point's coordinates back; OpenFOAM v1912's probes with
cellPoint in micrometre cells read their cell's first tetrahedron's
centroid instead
(tetrahedron::pointToBarycentric: |det| < SMALL = 1e-15 m^3 is taken as
degenerate and the coordinates (1/4, 1/4, 1/4, 1/4) returned), which
depends on the cell's face order, so on the decomposition: with --np N
the same is done on N ranks (decomposePar with the case's
system/decomposeParDict and constant/cellDecomposition: the run's own
decomposition). movingMeshProbes' cellPoint did the same until its
scaleFreeCellPointWeight (src/fsi, 2026-12-06): runs made before that
sampled the points "probes" reads back.

Prints, per probe: the nominal point, the point read back by each scheme
and rank count [um], and the height error [um]. The mesh is the one at
rest (time 0): a probe inside the moving band (interface
motionDistance) samples a point that moves with the mesh.

--out DIR (with a finished case): also a copy of CASE's inputs and
postProcessing/fluidProbes in DIR whose probe file names, in its header,
the points OpenFOAM's probes read back on --np ranks (where a run made
before scaleFreeCellPointWeight sampled), and planeWave
-dz 50e-9 -check (checkQuarterRun.sh's exceptions) run there: the
scene's probes against the 1D answer at the heights they sampled.
"""

import argparse
import os
import re
import shutil
import subprocess
import sys
import tempfile

import numpy as np

from neuronFsi import script  # noqa: E402
# an input's error is one line, not a traceback (adv52 p18)
script.guard()
from neuronFsi import planeWave
from neuronFsi import scratch

FUNCS = """
functions
{{
    ppProbes
    {{
        type probes; libs ("libsampling.so");
        fields (Cx Cy Cz); interpolationScheme cellPoint;
        probeLocations ({loc});
    }}
    ppCellPoint
    {{
        type movingMeshProbes; libs ("libfsi.so");
        fields (Cx Cy Cz); interpolationScheme cellPoint;
        probeLocations ({loc});
    }}
    ppFit
    {{
        type movingMeshProbes; libs ("libfsi.so");
        fields (Cx Cy Cz); interpolationScheme cellLinearFit;
        probeLocations ({loc});
    }}
}}
"""


SCHEMES = (("probes", "ppProbes"), ("cellPoint", "ppCellPoint"),
           ("fit", "ppFit"))


def run(cmd, cwd, log):
    with open(os.path.join(cwd, log), "w") as f:
        r = subprocess.run(cmd, cwd=cwd, stdout=f, stderr=subprocess.STDOUT)
    if r.returncode:
        sys.exit("probePoints.py: %s failed (exit %d; %s in %s)"
                 % (" ".join(cmd), r.returncode, log, cwd))


def locations(case):
    cd = os.path.join(case, "system", "controlDict")
    r = subprocess.run(["foamDictionary", "-entry",
                        "functions/fluidProbes/probeLocations", "-value", cd],
                       capture_output=True, text=True)
    if r.returncode != 0:
        # a folder that is no case, or no fluid probes (adv52 p18: a
        # traceback)
        sys.exit("probePoints.py: error: %s: no functions/fluidProbes/"
                 "probeLocations (foamDictionary: %s)"
                 % (cd, (r.stderr.strip().splitlines() or ["failed"])[-1]))
    out = r.stdout
    v = [float(x) for x in re.findall(r"[-+0-9.eE]+", out)]
    return np.array(v).reshape(-1, 3)


def lastRow(path):
    with open(path) as f:
        rows = [r for r in f if r.strip() and not r.startswith("#")]
    return np.array(rows[-1].split()[1:], float)


def readBack(work, name):
    d = os.path.join(work, "postProcessing", name, "0")
    return np.stack([lastRow(os.path.join(d, c)) for c in ("Cx", "Cy", "Cz")],
                    axis=1)


def sample(case, loc, np_):
    """{(scheme, ranks): points read back (n x 3)}."""
    out = {}
    tmp = tempfile.mkdtemp()
    try:
        work = os.path.join(tmp, "case")
        scratch.copyInputs(case, work, ["constant", "system", "0"])
        # the Allrun's probe locations and no other function object
        cd = os.path.join(work, "system", "controlDict")
        with open(cd) as f:
            text = f.read()
        text = re.sub(r"\n#sinclude \"controlDict.allrun\"", "\n", text)
        text = text[:text.index("\nfunctions")] + "\n" + text[
            text.index("\n}", text.index("\nfunctions")) + 2:]
        with open(cd, "w") as f:
            f.write(text + FUNCS.format(loc=" ".join(
                "(%.17g %.17g %.17g)" % tuple(x) for x in loc)))
        run(["postProcess", "-time", "0", "-funcs", "(writeCellCentres)"],
            work, "log.centres")
        run(["postProcess", "-time", "0", "-fields", "(Cx Cy Cz)"], work,
            "log.serial")
        for s, n in SCHEMES:
            out[(s, 1)] = readBack(work, n)
        if np_ > 1:
            shutil.rmtree(os.path.join(work, "postProcessing"))
            run(["decomposePar", "-force", "-time", "0"], work, "log.decompose")
            run(["mpirun", "-np", str(np_), "--bind-to", "none", "postProcess",
                 "-parallel", "-time", "0", "-fields", "(Cx Cy Cz)"], work,
                "log.parallel")
            for s, n in SCHEMES:
                out[(s, np_)] = readBack(work, n)
    finally:
        shutil.rmtree(tmp)
    return out


def planeWaveAt(case, out, points):
    """planeWave in a copy of case whose fluidProbes header names points."""
    if os.path.exists(out):
        sys.exit("probePoints.py: %s exists" % out)
    scratch.copyInputs(case, out, ["constant", "system", "0"])
    src = os.path.join(case, "postProcessing", "fluidProbes")
    dst = os.path.join(out, "postProcessing", "fluidProbes")
    shutil.copytree(src, dst)
    for root, _, files in os.walk(dst):
        for fn in files:
            path = os.path.join(root, fn)
            with open(path) as f:
                lines = f.readlines()
            for i, line in enumerate(lines):
                m = re.match(r"# Probe (\d+) \(", line)
                if m:
                    k = int(m.group(1))
                    lines[i] = "# Probe %d (%.10g %.10g %.10g)\n" % (
                        k, *points[k])
            with open(path, "w") as f:
                f.writelines(lines)
    r = subprocess.run(["planeWave", "-case", out, "-dz", "50e-9", "-check",
                        "-except", "solid:vonMises1ns,solid:strain1ns,"
                        "solid:restVonMises"],
                       capture_output=True, text=True)
    with open(os.path.join(out, "log.planeWave"), "w") as f:
        f.write(r.stdout + r.stderr)
    with open(os.path.join(out, "postProcessing", "planeWave", "0",
                           "measures.dat")) as f:
        sys.stdout.write(f.read())
    for line in r.stdout.splitlines():
        if line.startswith("FAIL"):
            print(line)
    print("planeWave exit %d (%s)" % (r.returncode, out))


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("case")
    p.add_argument("--np", type=int, default=1)
    p.add_argument("--out")
    a = p.parse_args()
    case = os.path.abspath(a.case)
    loc = locations(case)
    got = sample(case, loc, a.np)
    k = 1 if planeWave.isWedge(case) else 2     # the height's axis
    print("# probe: nominal point [um]; point read back by scheme/ranks [um] "
          "(height error [um])")
    for i, x in enumerate(loc):
        print("fluidProbes %d: (%.3f, %.3f, %.3f)" % (i, *(1e6*x)))
        for (s, n), y in sorted(got.items()):
            print("    %-9s %d rank%s: (%.3f, %.3f, %.3f) (%+.3f)"
                  % (s, n, "" if n == 1 else "s", *(1e6*y[i]),
                     1e6*(y[i, k] - x[k])))
    if a.out:
        planeWaveAt(case, os.path.abspath(a.out), got[("probes", a.np)])


if __name__ == "__main__":
    main()

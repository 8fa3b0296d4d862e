"""The paper comparison (issue 20 item 4): the paper's numbers and the
comparisons (neuronFsi.paper), where runs are found and when they are
current (neuronFsi.paperCases), and the command (applications/utilities/
paperFigures) run on small synthetic results of the six runs: its outputs
exist and the numbers it compares are those of the files."""
import json
import os
import shutil
import subprocess
import sys

import h5py
import numpy as np

from fixtures import TempDirTestCase
from neuronFsi import paper, paperCases
from neuronFsi import resultDigest

ROOT = os.path.normpath(os.path.join(os.path.dirname(__file__), "..", ".."))
COMMAND = os.path.join(ROOT, "applications", "utilities", "paperFigures",
                       "paperFigures.py")
um = 1e-6


class QuotedBar(TempDirTestCase):

    def testDigitsPrinted(self):
        for text, lo, hi in (("300", 250, 350), ("30", 25, 35),
                             ("0.1", 0.05, 0.15), ("11.5", 11.45, 11.55),
                             ("5", 4.5, 5.5), ("70", 65, 75),
                             ("1.67", 1.665, 1.675)):
            a, b = paper.quotedBar(text)
            self.assertAlmostEqual(a, lo, places=12, msg=text)
            self.assertAlmostEqual(b, hi, places=12, msg=text)

    def testQuotedInSI(self):
        v, lo, hi = paper.quoted("maximum compression")
        self.assertAlmostEqual(v, 70e-9)
        self.assertAlmostEqual(lo, 65e-9)
        self.assertAlmostEqual(hi, 75e-9)


# ------------------------------------------------------------ synthetic cell
# r-z quads on the grid r, z in (0, 1, 2, 2.1) um: the element (i, j) (i
# along r, j along z) is membrane when i or j is 2, nucleus at (0, 0),
# cytoplasm else. Cell: diameter 4.2, height 2.1, nucleus 2 x 1, membrane
# 0.1 um.
NAMES = ["nucleus", "cytoplasm", "membrane"]
GRID = np.array([0, 1, 2, 2.1])*um


def cell2D():
    X = np.array([(r, z, 0) for z in GRID for r in GRID])
    n = len(GRID)
    conn, region = [], []
    for j in range(3):
        for i in range(3):
            a = j*n + i
            conn.append((a, a + 1, a + n + 1, a + n))
            region.append(2 if 2 in (i, j) else 0 if (i, j) == (0, 0) else 1)
    return X, np.array(conn), np.array(region)


def cell3D():
    n = len(GRID)
    X = np.array([(x, y, z) for z in GRID for y in GRID for x in GRID])
    conn, region = [], []

    def node(i, j, k):
        return (k*n + j)*n + i
    for k in range(3):
        for j in range(3):
            for i in range(3):
                conn.append([node(i + a, j + b, k + c) for a, b, c in
                             ((0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0),
                              (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1))])
                region.append(2 if 2 in (i, j, k) else
                              0 if (i, j, k) == (0, 0, 0) else 1)
    return X, np.array(conn), np.array(region)


# pressure and von Mises per region: the jumps are the paper's 300, 30 Pa
P = np.array([10.0, 40.0, -260.0])
VM = np.array([50.0, 20.0, 80.0])


class Comparisons(TempDirTestCase):

    def testJumpsOuterMinusInner(self):
        X, conn, region = cell2D()
        j = paper.interfaceJumps(X, conn, region, P[region], NAMES)
        self.assertEqual(sorted(j), ["cytoplasm-nucleus",
                                     "membrane-cytoplasm"])
        np.testing.assert_allclose(j["membrane-cytoplasm"][0], -300)
        np.testing.assert_allclose(j["cytoplasm-nucleus"][0], 30)
        self.assertEqual(len(j["cytoplasm-nucleus"][0]), 2)   # two edges
        self.assertEqual(len(j["membrane-cytoplasm"][0]), 4)
        # the midpoints lie on the interface
        x = j["cytoplasm-nucleus"][1]
        self.assertTrue(np.all((np.isclose(x[:, 0], um)) |
                               np.isclose(x[:, 1], um)))
        r = paper.relativeJumps(conn, region, P[region], NAMES)
        # cytoplasm-nucleus: |jump| 30 over the median |p| of (10, 40, 40)
        self.assertAlmostEqual(r["cytoplasm-nucleus"], 30/40)
        # a field without jumps
        r = paper.relativeJumps(conn, region, np.full(len(conn), 5.0),
                                NAMES)
        self.assertEqual(max(r.values()), 0)

    def testJumps3D(self):
        X, conn, region = cell3D()
        j = paper.interfaceJumps(X, conn, region, P[region], NAMES)
        np.testing.assert_allclose(j["membrane-cytoplasm"][0], -300)
        self.assertEqual(len(j["cytoplasm-nucleus"][0]), 3)    # three faces

    def testGeometryAndInterfaceElements(self):
        X, conn, region = cell2D()
        g = paper.geometry(X, conn, region, NAMES)
        for k, v in (("cell diameter", 4.2), ("cell height", 2.1),
                     ("nucleus diameter", 2), ("nucleus height", 1),
                     ("membrane thickness", 0.1)):
            self.assertAlmostEqual(g[k], v*um, places=15, msg=k)
        m = paper.interfaceElements(conn, region)
        self.assertTrue(m.all())        # every element touches another here

    def testStageRates(self):
        rows = [(0, 0, 0, "A"), (1, 0.3e-6, 0, "A"), (2, 0.6e-6, 0, "A"),
                (3, 0.6e-6, 0, "B"), (4, 0.6e-6, 0, "B"),
                (4.1, 1.6e-6, 0, "C1"), (4.2, 0.6e-6, 0, "C1")]
        r = paper.stageRates(rows)
        self.assertAlmostEqual(r["A"], 0.3e-6)
        self.assertEqual(r["B"], 0)
        self.assertAlmostEqual(r["C1"], 10e-6)


# ------------------------------------------------------------- the command

def writeH5(path, X, conn, region, steps):
    """solid.h5 as the solid library writes it: steps [(t, {field})]"""
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with h5py.File(path, "w") as f:
        f["mesh/coordinates"] = X
        f["mesh/connectivity"] = conn
        f["mesh/region"] = region
        for k, (t, fields) in enumerate(steps):
            g = f.create_group("steps/%d" % k)
            g.attrs["time"] = t
            g["displacement"] = np.zeros_like(X)
            for name, v in fields.items():
                g[name] = v


def writeMsh(path, dim):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        f.write("$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$PhysicalNames\n4\n"
                "%d 9 \"axis\"\n%d 1 \"nucleus\"\n%d 2 \"cytoplasm\"\n"
                "%d 3 \"membrane\"\n$EndPhysicalNames\n"
                % (dim - 1, dim, dim, dim))


def read(path):
    with open(path) as f:
        return f.read()


def write(path, text):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        f.write(text)
    # a synthetic result as its run would have written it: with the
    # digests the readers verify (neuronFsi.resultDigest)
    if os.sep + "postProcessing" + os.sep in path:
        resultDigest.writeSidecar(path)


ALLRUN = {
    "indentation": "#!/bin/bash\nallrunOptions \"\" \"$@\" < /dev/null\n",
    "preview": "#!/bin/bash\nallrunOptions \"\" \"$@\" <<'OPTIONS'\n"
               "-pulse  pulse  number(0,1e-6]  s\nOPTIONS\n",
    "quarter": "#!/bin/bash\nallrunOptions \"\" \"$@\" <<'OPTIONS'\n"
               "-np  np  integer[1,4096]  -\n"
               "-lateral  lateral  number(0,1)  m\n"
               "-far  far  number(0,1)  m\n"
               "-cell  cell  number(0,1)  m\n"
               "-inflow  inflow  number(0,1)|none  m\nOPTIONS\n",
}
TUTORIALS = {"indentation/averageCell": "indentation",
             "indentation/validationCell": "indentation",
             "blast/axisymmetricPreview": "preview",
             "blast/quarter3D": "quarter"}
PEAKS = ["endB"] + paper.TABLE3_LABELS + ["endE"]
PULSE_P = {5e-9: 70e6, 10e-9: 100e6, 15e-9: 101e6}      # probe peaks [Pa]
PULSE_VM = {5e-9: 7.0, 10e-9: 14.0, 15e-9: 21.0}        # [Pa]
Z_PROBE = 1.5*um


def pulseFile(T):
    return ("FoamFile { version 2.0; format ascii; class volScalarField; "
            "object p; }\ndimensions [1 -1 -2 0 0 0 0];\n"
            "internalField uniform 1e5;\nboundaryField\n{\n    top\n    {\n"
            "        type uniformFixedValue;\n        uniformValue table\n"
            "        ( (0 0) (1e-10 5e7) (%.10g 5e7) (%.10g 0) (1 0) );\n"
            "    }\n}\n" % (T, T + 1e-10))


def obliqueCell(h=0.1*um):
    """r-z quads of size h on [0, 4] x [0, 4] um: nucleus below the line
    z = 2 um - r/2 (by centroid), cytoplasm above it; the interface is a
    staircase along that line, normal (1, 2)/sqrt(5) outwards."""
    n = int(round(4*um/h)) + 1
    g = np.linspace(0, 4*um, n)
    X = np.array([(r, z, 0) for z in g for r in g])
    conn, region = [], []
    for j in range(n - 1):
        for i in range(n - 1):
            a = j*n + i
            conn.append((a, a + 1, a + n + 1, a + n))
            r, z = g[i] + h/2, g[j] + h/2
            region.append(0 if z < 2*um - r/2 else 1)
    return X, np.array(conn), np.array(region)


class InterfaceNormalProfile(TempDirTestCase):

    def testObliqueInterface(self):
        X, conn, region = obliqueCell()
        exact = np.array([1.0, 2.0])/np.sqrt(5)
        # the ray through (2, 1) um meets the line at (2, 1) um
        p = paper.interfaceNormalProfile(X, conn, region, NAMES,
                                         "cytoplasm-nucleus", (2, 1),
                                         half=1*um, band=0.1*um)
        self.assertLess(np.degrees(np.arccos(p["normal"] @ exact)), 5)
        self.assertLess(np.linalg.norm(p["origin"] - np.array([2, 1])*um),
                        0.15*um)
        s, e = p["s"], p["elements"]
        self.assertTrue(np.all(np.diff(s) >= 0))
        self.assertTrue(np.all(np.abs(s) <= 1*um))
        self.assertGreater(s.max(), 0.9*um)
        self.assertLess(s.min(), -0.9*um)
        # outer (cytoplasm) on the positive side, away from the staircase
        far = np.abs(s) > 0.15*um
        np.testing.assert_array_equal(region[e][far], (s[far] > 0)*1)
        # every element within the band of the normal line
        cen = X[conn[e], :2].mean(axis=1) - p["origin"]
        t = np.array([p["normal"][1], -p["normal"][0]])
        self.assertTrue(np.all(np.abs(cen @ t) <= 0.1*um + 1e-15))

    def testPoints(self):
        X, conn, region = obliqueCell()
        mids, outs, ins = paper.interfaceSides(X, conn, region, NAMES,
                                               "cytoplasm-nucleus")
        self.assertTrue(np.all(region[outs] == 1))
        self.assertTrue(np.all(region[ins] == 0))
        top = mids[paper.interfacePoint(mids, "top")]
        side = mids[paper.interfacePoint(mids, "side")]
        self.assertLess(top[0], 0.1*um)           # at the axis
        self.assertGreater(top[1], 1.9*um)
        self.assertGreater(side[0], 3.8*um)       # farthest from the axis
        self.assertLess(side[1], 0.1*um)
        # the pole's normal is the line's, pointing up into the cytoplasm
        p = paper.interfaceNormalProfile(X, conn, region, NAMES,
                                         "cytoplasm-nucleus", "top")
        self.assertGreater(p["normal"][1], 0.8)

    def testRefused(self):
        X, conn, region = obliqueCell()
        with self.assertRaises(ValueError):
            paper.interfaceSides(X, conn, region, NAMES, "membrane-cytoplasm")
        with self.assertRaises(ValueError):
            paper.interfacePoint(np.zeros((2, 2)), "bottom")
        X3, conn3, region3 = cell3D()
        with self.assertRaises(ValueError):
            paper.interfaceSides(X3, conn3, region3, NAMES,
                                 "cytoplasm-nucleus")


class Command(TempDirTestCase):
    """The command on synthetic results of the six runs."""

    def setUp(self):
        super().setUp()
        self.project = os.path.join(self.tmp, "project", "tutorials")
        self.results = os.path.join(self.tmp, "results")
        self.case = os.path.join(self.tmp, "paper")
        thermo = read(os.path.join(ROOT, "tutorials", "blast",
                                   "axisymmetricPreview", "constant",
                                   "thermophysicalProperties"))
        for rel, kind in TUTORIALS.items():
            d = os.path.join(self.project, rel)
            write(os.path.join(d, "Allrun"), ALLRUN[kind])
            write(os.path.join(d, "system", "controlDict"), "// %s\n%s"
                  % (rel, "endTime 1e-7;\n" if kind != "indentation"
                     else ""))
            if kind != "indentation":
                write(os.path.join(d, "constant",
                                   "thermophysicalProperties"), thermo)
                write(os.path.join(d, "0.orig", "p"), pulseFile(5e-9))
        git = ["git", "-C", self.project, "-c", "user.name=t",
               "-c", "user.email=t@t"]
        for cmd in (["init", "-q"], ["add", "."], ["commit", "-q", "-m", "t"]):
            subprocess.run(git + cmd, check=True, capture_output=True)
        shutil.copytree(self.project, self.results,
                        ignore=shutil.ignore_patterns(".git"))
        self.indentation(os.path.join(self.results, "indentation",
                                      "averageCell"), 1.0)
        self.indentation(os.path.join(self.results, "indentation",
                                      "validationCell"), 0.5)
        self.blast(os.path.join(self.results, "blast",
                                "axisymmetricPreview"), 5e-9, {})
        self.blast(os.path.join(self.results, "blast", "quarter3D"), 5e-9,
                   {"-np": "2", "-cell": "0.7e-6", "-lateral": "2e-6",
                    "-far": "10e-6", "-inflow": "14e-6"}, True)
        for T in (10e-9, 15e-9):
            d = os.path.join(self.case, "postProcessing", "runs",
                             "blast%dns" % round(T*1e9))
            shutil.copytree(os.path.join(self.project, "blast",
                                         "axisymmetricPreview"), d)
            self.blast(d, T, {"-pulse": "%g" % T})
        write(os.path.join(self.case, "system", "paperDict"), read(
            os.path.join(ROOT, "tutorials", "paper", "system", "paperDict")))

    def log(self, d, solver):
        write(os.path.join(d, "log." + solver),
              "ExecutionTime = 1.5 s  ClockTime = 2 s\n\nEnd\n")

    def indentation(self, d, scale):
        """peaks [nN] = scale x (index + 1); pressures P, von Mises VM"""
        pp = os.path.join(d, "postProcessing", "indentation")
        times = {l: 10.0 + k for k, l in enumerate(PEAKS)}
        times["C2,ii"] = 26.9
        write(os.path.join(pp, "peaks.dat"),
              "# label  time [s]  depth [m]  force [N]\n" + "".join(
                  "%s %.10g 3.41e-06 %.10g\n" % (l, times[l],
                                                 scale*(k + 1)*1e-9)
                  for k, l in enumerate(PEAKS)))
        rows, t, z = [], 0.0, 0.0
        for st, load, rate in paper.TABLE1:
            for k in range(3):
                rows.append("%.10g %.10g 1e-9 %.10g 0 %s\n" % (t, z, t*1e-7,
                                                              st))
                t += 1.0
                z += rate*1e-6*(1 if k < 2 else -1)
        write(os.path.join(pp, "force.dat"),
              "# time [s]  depth [m]  force [N]  contactRadius [m]  "
              "maxPenetration [m]  stage\n" + "".join(rows))
        write(os.path.join(pp, "materials.dat"),
              "# region  rho0 [kg/m^3]  C10 [Pa]  d0 [1/Pa]  muN [Pa]  tauN"
              " [s]\nnucleus 1000 6.67 0 431.12 0.5\n"
              "cytoplasm 1000 1.67 0 107.78 0.01\n"
              "membrane 1000 166.67 0 13.89 3000\n")
        X, conn, region = cell2D()
        writeH5(os.path.join(pp, "solid.h5"), X, conn, region, [
            (times[l], {"pressure": P[region], "vonMises": VM[region],
                        "temperatureRise": np.zeros(len(conn))})
            for l in PEAKS])
        writeMsh(os.path.join(d, "constant", "cell.msh"), 2)
        self.log(d, "cellIndentationFoam")

    def blast(self, d, T, options, threeD=False):
        X, conn, region = cell3D() if threeD else cell2D()
        dT = np.linspace(0, 0.12, len(conn))
        writeH5(os.path.join(d, "solid", "solid.h5"), X, conn, region, [
            (0.0, {"pressure": np.zeros(len(conn)),
                   "vonMises": np.zeros(len(conn)),
                   "temperatureRise": np.zeros(len(conn))}),
            (65.5e-9, {"pressure": 50e6 + region*0.5e6,
                       "vonMises": VM[region]*0.5,
                       "temperatureRise": dT})])
        writeMsh(os.path.join(d, "constant", "cell.msh"), 3 if threeD else 2)
        # the mesh sizes as the Allruns leave them in the case
        write(os.path.join(d, "system", "cellMeshDict"),
              "nucleusSize 0.7e-6;\ncytoplasmSize 0.7e-6;\n"
              "membraneSize 0.5e-6;\nfluid\n{\n    nearSize 0.5e-6;\n"
              "    farSize 10e-6;\n    hexCoeffs { axialSize 0.5e-6; "
              "lateralSize 2e-6; }\n}\n" if threeD else
              "nucleusSize 3.5e-7;\ncytoplasmSize 3.5e-7;\n"
              "membraneSize 2.8e-7;\n")
        if not threeD:
            write(os.path.join(d, "system", "blockMeshDict"),
                  "// Generated by tutorials/blast/fluidWedgeMesh.py\n"
                  "// Water column r <= 50 um, z <= 20 um minus the cell\n"
                  "// D = 16.8 um, H = 7.9 um), wedge 5 deg about the y "
                  "axis; sizes 0.175/0.7 um,\n// axial size 0.175 um "
                  "above the inner box, radial size 5.6 um at r = R\n")
            write(os.path.join(d, "constant", "polyMesh", "boundary"),
                  "front { type wedge; }\n")
        write(os.path.join(d, "0", "p"), pulseFile(T))   # the Allrun's
        t = np.linspace(0, 100e-9, 201)
        shape = np.clip(1 - np.abs(t - 70e-9)/5e-9, 0, None)
        p, vm = PULSE_P[T]*shape, PULSE_VM[T]*shape
        ez = -0.01*shape*(T/5e-9)
        rate = np.gradient(ez, t)
        heat = 0.1*np.clip((t - 60e-9)/5e-9, 0, 1)   # 0.1 K in 5 ns
        pt = (2*um, Z_PROBE, 0) if not threeD else (2*um, 0, Z_PROBE)
        pp = os.path.join(d, "postProcessing")
        write(os.path.join(pp, "solidProbes", "0", "solidProbes.dat"),
              "# solid probes\n# time [s]  p0[Pa] vonMises0[Pa] strain0[-] "
              "strainRate0[1/s] dT0[K]  strainZ0[-] strainRateZ0[1/s]\n"
              "# probe 0 interfaceProbe at (%.10g %.10g %.10g) m in "
              "cytoplasm: element 4, patch of 6 elements\n" % pt
              + "".join("%.10g %.10g %.10g 0 0 %.10g %.10g %.10g\n" % r
                        for r in zip(t, p, vm, heat, ez, rate)))
        write(os.path.join(pp, "solidInterfaces", "0",
                           "interfaceMaxima.dat"),
              "# time [s]  pMax:membrane-cytoplasm[Pa] "
              "vonMisesMax:membrane-cytoplasm[Pa]\n0 0 0\n")
        write(os.path.join(pp, "fsi", "0", "coupling.dat"),
              "# time [s]  dt [s]  iterations  residual [-]  converged\n"
              + "".join("%.10g 1e-12 2 1e-5 1\n" % x for x in t))
        write(os.path.join(pp, "planeWave", "0", "reference.dat"),
              "# 1D plane wave\n# time [s]  p_z%.17g[Pa]\n" % Z_PROBE
              + "".join("%.10g %.10g\n" % (a, 0.9*b) for a, b in zip(t, p)))
        write(os.path.join(d, ".allrunOptions"), json.dumps(
            {"program": "Allrun", "options": options}))
        self.log(d, "cellBlastFoam")

    def paperFigures(self, *args):
        env = dict(os.environ, FOAM_TUTORIALS=self.project,
                   PYTHONPATH=os.path.join(ROOT, "src", "python"))
        return subprocess.run(
            [sys.executable, COMMAND, "-case", self.case, "-results",
             self.results, "-noRun"] + list(args), env=env,
            capture_output=True, text=True, timeout=300)

    def testOutputsAndNumbers(self):
        out = os.path.join(self.tmp, "out")
        r = self.paperFigures("-output", out)
        self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
        for name in ("README.md", "results.json", "fig2_mesh.png",
                     "fig4-6_forceDepth.png", "table3_validation.png",
                     "fig7-8_indentation_C2ii.png",
                     "fig7-8_indentation_C1i.png", "fig7-9_blast_2D.png",
                     "fig7-9_blast_3D.png", "fig7-9_printedNumbers.png",
                     "fig10_pulses.png", "fig10_ratios.png"):
            p = os.path.join(out, name)
            self.assertTrue(os.path.isfile(p), name)
            self.assertLess(os.path.getsize(p), 300e3, name)
        res = json.loads(read(os.path.join(out, "results.json")))
        # where each run came from
        self.assertEqual(res["runs"]["blast5ns"]["results"],
                         "the main job's, tutorials/blast/axisymmetricPreview")
        self.assertEqual(res["runs"]["blast10ns"]["results"], os.path.join(
            self.case, "postProcessing", "runs", "blast10ns"))
        # Table 3: the validation cell's peaks, 0.5 x (index + 1) nN
        np.testing.assert_allclose(res["table3"]["ours"],
                                   [0.5e-9*(k + 2) for k in range(9)])
        np.testing.assert_allclose(res["table3"]["paperExp"],
                                   np.array(paper.TABLE3_EXP)*1e-9)
        # F_B, F_E of the average cell: the first and last peaks
        self.assertAlmostEqual(res["fig4-6"]["F_B"]["ours"], 1e-9)
        self.assertAlmostEqual(res["fig4-6"]["F_E"]["ours"], 11e-9)
        # Table 1: the rates the synthetic force.dat moves at
        for st, load, rate in paper.TABLE1:
            self.assertAlmostEqual(res["table1"][st]["ours"], rate*1e-6,
                                   msg=st)
        # Fig. 2 from the synthetic mesh
        self.assertAlmostEqual(res["fig2"]["cell diameter"]["ours"], 4.2*um)
        self.assertAlmostEqual(res["fig2"]["membrane thickness"]["ours"],
                               0.1*um)
        # the indentation at 26.88 s (the write at 26.9 s) and C1,i
        ind = res["fig7-8indentation"]
        self.assertEqual(ind["stated"]["label"], "C2,ii")
        self.assertAlmostEqual(ind["stated"]["time"], 26.9)
        self.assertEqual(ind["reading"]["label"], "C1,i")
        for key in ("stated", "reading"):
            j = ind[key]["jumps"]
            self.assertAlmostEqual(j["membrane-cytoplasm"]["underIndenter"],
                                   -300)
            self.assertAlmostEqual(j["cytoplasm-nucleus"]["underIndenter"],
                                   30)
            self.assertAlmostEqual(ind[key]["vonMisesMaxValue"], 80)
            # force.dat's row nearest the peak (a row a second, 0-20 s)
            self.assertAlmostEqual(ind[key]["contactRadius"],
                                   min(round(ind[key]["time"]), 20)*1e-7)
            self.assertEqual(ind[key]["vonMisesMax"]["region"], "membrane")
            c = ind[key]["vonMisesMaxCytoplasmNucleus"]
            self.assertEqual((c["region"], c["value"]), ("nucleus", 50))
        # the blast at 65.5 ns
        for key in ("blast5ns", "quarter3D"):
            b = res["fig7-9blast"][key]
            self.assertAlmostEqual(b["time"], 65.5e-9)
            self.assertAlmostEqual(b["temperatureRiseMax"], 0.12)
            self.assertAlmostEqual(b["vonMisesMaxValue"], 40)
            self.assertAlmostEqual(b["pressureMax"], 51e6)
            self.assertAlmostEqual(
                b["jumps"]["membrane-cytoplasm"]["maxAbs"], 0.5e6)
            self.assertAlmostEqual(b["probePressurePeakTime"], 70e-9)
            self.assertAlmostEqual(b["probeTemperatureRise"], 0.1)
            self.assertAlmostEqual(b["probeTemperatureRiseTime"], 4e-9)
            self.assertAlmostEqual(b["writeInterval"], 65.5e-9)
        # Fig. 10: the probe's peaks and the plane wave's
        f10 = res["fig10"]
        for k, T in enumerate(paper.FIG10_DURATIONS):
            self.assertAlmostEqual(f10["ours"][k]["pressure"], PULSE_P[T])
            self.assertAlmostEqual(f10["ours"][k]["vonMises"], PULSE_VM[T])
            self.assertAlmostEqual(f10["ours"][k]["strain"], 0.01*T/5e-9)
            self.assertAlmostEqual(f10["planeWave"][k]["pressure"],
                                   0.9*PULSE_P[T])
        self.assertAlmostEqual(f10["probeHeight"], Z_PROBE)
        self.assertAlmostEqual(f10["echoTime"], 2*Z_PROBE/1450)
        checks = dict(res["checks"])
        self.assertTrue(checks["Fig. 10: von Mises doubles and triples "
                               "(ours x2.00, x3.00; within 25 %)"])
        text = read(os.path.join(out, "README.md"))
        self.assertIn("| C2,ii (26.90 s) | membrane-cytoplasm | ~300 | "
                      "-300.0 |", text)
        # the mesh sizes each blast run was made with
        self.assertIn("| water 0.175 at the cell, 0.7 across the column, "
                      "0.175 along z; cell 0.35 / 0.35 (membrane 0.28) |",
                      text)
        self.assertIn("| water 0.5 at the cell, 2 in the inner box, 10 at "
                      "the side walls, 0.5 along z; cell 0.7 / 0.7 "
                      "(membrane 0.5) |", text)

    def testStaleAndChangedRunsAreNotUsed(self):
        # an input of the tutorial edited after the run
        d = os.path.join(self.results, "indentation", "averageCell")
        write(os.path.join(d, "system", "controlDict"), "// changed\n")
        r = self.paperFigures("-output", os.path.join(self.tmp, "out"))
        self.assertNotEqual(r.returncode, 0)
        self.assertIn("system/controlDict differs from the tutorial's",
                      r.stdout)
        self.assertIn("averageCell: no current results (-noRun)", r.stderr)
        self.assertFalse(os.path.exists(os.path.join(self.tmp, "out")))

    def testFailureLeavesTheOutput(self):
        out = os.path.join(self.tmp, "out")
        write(os.path.join(out, "README.md"), "earlier\n")
        # a file the figures read that decides nothing of whether the run
        # is current (paperCases.why reads the probes since fix19i)
        reference = os.path.join(self.results, "blast",
                                 "axisymmetricPreview", "postProcessing",
                                 "planeWave", "0", "reference.dat")
        write(reference, read(reference).replace("\n0 ", "\nzero ", 1))
        r = self.paperFigures("-output", out)
        self.assertNotEqual(r.returncode, 0)
        self.assertIn("reference.dat", r.stderr)
        self.assertNotIn("Traceback", r.stderr)
        self.assertEqual(os.listdir(self.tmp).count("out"), 1)
        self.assertEqual(os.listdir(out), ["README.md"])
        self.assertEqual(read(os.path.join(out, "README.md")), "earlier\n")
        self.assertFalse([n for n in os.listdir(self.tmp)
                          if n.startswith(".paperFigures")])

    def testOtherOptionsAreNotUsed(self):
        run = paperCases.read(self.case, self.project)["cases"]["quarter3D"]
        folder = os.path.join(self.results, "blast", "quarter3D")
        self.assertIsNone(paperCases.why(run, folder))
        write(os.path.join(folder, ".allrunOptions"), json.dumps(
            {"program": "Allrun", "options": {"-np": "2", "-cell": "0.7e-6",
                                              "-lateral": "2e-6",
                                              "-far": "5e-6",
                                              "-inflow": "14e-6"}}))
        self.assertIn("-far 5e-6 then, 1e-05 now",
                      paperCases.why(run, folder))

    def testRunOfAnotherPulseOrCut(self):
        # a 15 ns run under the name blast10ns (adv pass pa19), in the
        # dictionary and in the results; a cut probe file (pa09); the
        # comparison's run folder a link or a file (pa25, pa26)
        path = os.path.join(self.case, "system", "paperDict")
        good = read(path)
        write(path, good.replace("options (-pulse 10e-9);",
                                 "options (-pulse 15e-9);"))
        r = self.paperFigures()
        self.assertEqual(r.returncode, 1, r.stderr)
        self.assertIn("entry 'cases/blast10ns/options': -pulse 1.5e-08 s is "
                      "not the pulse of blast10ns, 1e-08 s", r.stderr)
        write(path, good)
        cases = paperCases.read(self.case, self.project)["cases"]
        d10 = os.path.join(self.case, "postProcessing", "runs", "blast10ns")
        self.assertIsNone(paperCases.why(cases["blast10ns"], d10))
        write(os.path.join(d10, "0", "p"), pulseFile(15e-9))
        self.assertIn("its pulse lasts 1.5e-08 s (0/p), not the 1e-08 s of "
                      "blast10ns", paperCases.why(cases["blast10ns"], d10))
        probes = os.path.join(self.results, "blast", "axisymmetricPreview",
                              "postProcessing", "solidProbes", "0",
                              "solidProbes.dat")
        lines = read(probes).splitlines(True)
        write(probes, "".join(lines[:120]))
        self.assertIn("postProcessing/solidProbes/0/solidProbes.dat ends at "
                      "5.8e-08 s, before the run's "
                      "endTime 1e-07 s (system/controlDict): a cut or "
                      "truncated file", paperCases.why(
                          cases["blast5ns"], os.path.join(
                              self.results, "blast", "axisymmetricPreview")))
        shutil.rmtree(d10)
        os.symlink(self.results, d10)
        with self.assertRaisesRegex(paperCases.PaperError,
                                    "is a symbolic link .*move it away"):
            paperCases.make(cases["blast10ns"], self.case)
        self.assertTrue(os.path.isdir(self.results))
        os.remove(d10)
        write(d10, "a file\n")
        with self.assertRaisesRegex(paperCases.PaperError,
                                    "blast10ns is a file, not a folder"):
            paperCases.make(cases["blast10ns"], self.case)
        # a folder of the user's own there (not a run folder the
        # comparison made): kept, refused (adv44 a12: removed)
        os.remove(d10)
        write(os.path.join(d10, "notes.md"), "# my notes\n")
        write(os.path.join(d10, "myAnalysis", "fit.py"), "print(1)\n")
        with self.assertRaisesRegex(paperCases.PaperError,
                                    "blast10ns: .*blast10ns holds files that"
                                    " are not of a run of the comparison "
                                    ".*notes.md.*Nothing was changed"):
            paperCases.make(cases["blast10ns"], self.case)
        self.assertEqual(read(os.path.join(d10, "notes.md")), "# my notes\n")
        self.assertTrue(os.path.isfile(os.path.join(d10, "myAnalysis",
                                                    "fit.py")))

    def testBadDictionary(self):
        path = os.path.join(self.case, "system", "paperDict")
        good = read(path)
        for old, new, msg in (
                ("peakWindow      9e-8;", "peakWindow -1;",
                 "entry 'peakWindow' = -1 is outside the valid range"),
                ("options (-pulse 10e-9);", "options (-pulse 10e-3);",
                 "entry 'cases/blast10ns/options': option -pulse"),
                ("blast15ns", "blast51ns", "blast51ns")):
            write(path, good.replace(old, new))
            r = self.paperFigures()
            self.assertNotEqual(r.returncode, 0, old)
            self.assertIn(msg, r.stderr)
            self.assertIn("paperDict", r.stderr)
        write(path, good)


class UsersFilesInARunFolder(TempDirTestCase):
    """The folder of a run of the comparison is replaced only when it is an
    earlier run's (issue 19, adv44 a12; fix19za): a folder holding the
    user's files only, or an earlier run's folder holding a note of the
    user's, is refused naming the files, which are kept."""

    def folder(self, files):
        case = os.path.join(self.tmp, "paper")
        for f in files:
            self.write(os.path.join("paper", paperCases.RUNS, "averageCell",
                                    f), "mine %s\n" % f)
        run = {"name": "averageCell", "tutorial": os.path.join(
            ROOT, "tutorials", "indentation", "averageCell")}
        return case, run, os.path.join(case, paperCases.RUNS, "averageCell")

    def testUsersFolderKept(self):
        case, run, folder = self.folder(["notes.md", "myAnalysis/fit.py"])
        with self.assertRaises(paperCases.PaperError) as e:
            paperCases.make(run, case)
        self.assertIn("notes.md", str(e.exception))
        self.assertIn("myAnalysis/fit.py", str(e.exception))
        with open(os.path.join(folder, "myAnalysis", "fit.py")) as f:
            self.assertEqual(f.read(), "mine myAnalysis/fit.py\n")

    def cleared(self, folder, run):
        """paperCases.clear(run, folder): (where it went, what it said)."""
        import contextlib
        import io
        out = io.StringIO()
        with contextlib.redirect_stdout(out):
            aside = paperCases.clear(run, folder)
        return aside, out.getvalue()

    def testNoteInAnEarlierRunKept(self):
        # an interrupted run (its solver's log without End) of the
        # comparison, its Allrun's plots at its top and the user's note
        # (adv44 a43: refused naming the run's own plots as the user's, the
        # folder to be moved away by hand): moved aside whole, said
        case, run, folder = self.folder(["Allrun", "log.Allrun",
                                         "log.cellIndentationFoam",
                                         "indentation.png", "results.md",
                                         "notes.md"])
        run["kind"] = "indentation"
        aside, said = self.cleared(folder, run)
        self.assertEqual(aside, folder + ".interrupted")
        self.assertFalse(os.path.lexists(folder))
        for f in ("notes.md", "indentation.png", "log.Allrun"):
            with open(os.path.join(aside, f)) as g:
                self.assertEqual(g.read(), "mine %s\n" % f)
        self.assertRegex(said, r"averageCell: the folder of an interrupted "
                         r"run of the comparison, .*averageCell, holds files"
                         r" that may not be the run's \(indentation.png, "
                         r"notes.md, results.md\): moved whole to "
                         r".*averageCell.interrupted .*remove it when")
        # again: the next free name; a finished earlier run's: .earlier
        self.folder(["Allrun", "log.Allrun", "notes.md"])
        self.assertEqual(self.cleared(folder, run)[0],
                         folder + ".interrupted1")
        self.folder(["Allrun", "log.Allrun", "notes.md"])
        self.write(os.path.join(folder, "log.cellIndentationFoam"),
                   "Starting\nEnd\n")
        self.assertEqual(self.cleared(folder, run)[0], folder + ".earlier")
        for d in (".interrupted", ".interrupted1", ".earlier"):
            self.assertTrue(os.path.isfile(os.path.join(folder + d,
                                                        "notes.md")))

    def testRunsOwnFolderRemoved(self):
        # an earlier run's folder holding the tutorial's files and logs
        # only: replaced as before, nothing moved aside
        case, run, folder = self.folder(["Allrun", "log.Allrun",
                                         "log.cellIndentationFoam"])
        run["kind"] = "indentation"
        aside, said = self.cleared(folder, run)
        self.assertIsNone(aside)
        self.assertEqual(said, "")
        self.assertFalse(os.path.lexists(folder))
        self.assertEqual(os.listdir(os.path.dirname(folder)), [])

"""Outputs written by replacement (neuronFsi.script.replacing; issue 19,
adv44 a17, fix19za): calibrateCell wrote constant/solidProperties.calibrated
and postProcessing/calibration/results.md THROUGH symbolic links of the case
over the user's shared files outside it. A link at an output's path is
replaced by the output; the file it pointed to is kept unchanged; a write
that fails leaves the old file and no temporary one."""
import importlib.util
import os
import unittest

from fixtures import TempDirTestCase
from neuronFsi import script

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
CALIBRATE = os.path.join(ROOT, "applications", "utilities", "calibrateCell",
                         "calibrateCell.py")


def read(path):
    with open(path) as f:
        return f.read()


class Replacing(TempDirTestCase):
    def testLinkReplacedNotWrittenThrough(self):
        shared = self.write("shared/mine", "the user's\n")
        out = os.path.join(self.tmp, "out")
        os.symlink(shared, out)
        with script.replacing(out) as f:
            f.write("ours\n")
        self.assertFalse(os.path.islink(out))
        self.assertEqual(read(out), "ours\n")
        self.assertEqual(read(shared), "the user's\n")
        self.assertEqual(sorted(os.listdir(self.tmp)), ["out", "shared"])

    def testFailedWriteLeavesTheOldFile(self):
        out = self.write("out", "old\n")
        with self.assertRaises(RuntimeError):
            with script.replacing(out) as f:
                f.write("half")
                raise RuntimeError("stopped")
        self.assertEqual(read(out), "old\n")
        self.assertEqual(os.listdir(self.tmp), ["out"])


class Writing(TempDirTestCase):
    """script.writing, the writer of every Python tool's files (fix19k)"""

    def testHardLinkNotWrittenThrough(self):
        # adv54 n14: a case copied by cp -al; the copy's planeWave,
        # plotBlast.py wrote the original's files through the shared inodes
        a = self.write("a/postProcessing/planeWave/0/reference.dat", "A\n")
        os.makedirs(os.path.join(self.tmp, "b", "postProcessing",
                                 "planeWave", "0"))
        b = os.path.join(self.tmp, "b", "postProcessing", "planeWave", "0",
                         "reference.dat")
        os.link(a, b)
        with script.writing(b) as f:
            f.write("B\n")
        with open(a) as f:
            self.assertEqual(f.read(), "A\n")
        with open(b) as f:
            self.assertEqual(f.read(), "B\n")
        fig = self.write("b/fig.png", "mine")
        os.link(fig, os.path.join(self.tmp, "a", "fig.png"))
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        f = plt.figure()
        script.saveFigure(f, fig, dpi=20)
        plt.close(f)
        with open(os.path.join(self.tmp, "a", "fig.png")) as h:
            self.assertEqual(h.read(), "mine")

    def testFolderLinkLeavingTheCaseRefused(self):
        # adv54 v03: B's postProcessing/planeWave a link to A's
        for c in ("a", "b"):
            os.makedirs(os.path.join(self.tmp, c, "system"))
        a = self.write("a/postProcessing/planeWave/0/reference.dat", "A\n")
        os.makedirs(os.path.join(self.tmp, "b", "postProcessing"))
        os.symlink(os.path.join(self.tmp, "a", "postProcessing", "planeWave"),
                   os.path.join(self.tmp, "b", "postProcessing", "planeWave"))
        b = os.path.join(self.tmp, "b", "postProcessing", "planeWave", "0",
                         "reference.dat")
        with self.assertRaisesRegex(script.OutputLinkError,
                                    r"symbolic link leaving the case"):
            with script.writing(b) as f:
                f.write("B\n")
        with open(a) as f:
            self.assertEqual(f.read(), "A\n")
        # a link inside the case is the case's own
        os.makedirs(os.path.join(self.tmp, "b", "mine"))
        os.symlink(os.path.join(self.tmp, "b", "mine"),
                   os.path.join(self.tmp, "b", "out"))
        with script.writing(os.path.join(self.tmp, "b", "out", "x")) as f:
            f.write("x\n")

    def testFailedWriteKeepsTheFile(self):
        # adv53 l09: fluidWedgeMesh.py on a full disk left a 0-byte file
        p = self.write("blockMeshDict", "old\n")
        with self.assertRaises(RuntimeError):
            with script.writing(p) as f:
                f.write("new")
                raise RuntimeError("disk full")
        with open(p) as f:
            self.assertEqual(f.read(), "old\n")
        self.assertEqual(sorted(os.listdir(self.tmp)), ["blockMeshDict"])


class Model:
    def solid_properties(self, cal):
        return "/*---*\\\n\\*---------*/\nmaterials {}\n"

    def indenter_properties(self, delta0):
        return "delta0 %g;\n" % delta0


class CalibrateCellOutputs(TempDirTestCase):
    def testLinksOfTheCaseReplaced(self):
        spec = importlib.util.spec_from_file_location("calibrateCell",
                                                      CALIBRATE)
        cc = importlib.util.module_from_spec(spec)
        spec.loader.exec_module(cc)
        case = os.path.join(self.tmp, "cal")
        os.makedirs(os.path.join(case, "constant"))
        pp = os.path.join(case, "postProcessing", "calibration")
        os.makedirs(pp)
        links = {os.path.join(case, "constant",
                              "solidProperties.calibrated"): "materials",
                 os.path.join(case, "constant",
                              "indenterProperties.calibrated"): "indenter",
                 os.path.join(pp, "results.md"): "report",
                 os.path.join(pp, "evaluations.csv"): "evaluations",
                 os.path.join(pp, "parameters.csv"): "parameters"}
        for link, name in links.items():
            os.symlink(self.write("shared/" + name, "mine " + name + "\n"),
                       link)

        class Fake:
            pass
        c = Fake()
        c.case, c.dict_path = case, os.path.join(case, "system", "calDict")
        c.model, c.free, c.history, c.fitted = Model(), [], [], []
        cc.Calibration.write(c, {}, {"delta0": 1e-7}, "results\n")
        for link, name in links.items():
            self.assertFalse(os.path.islink(link), link)
            self.assertEqual(read(os.path.join(self.tmp, "shared", name)),
                             "mine " + name + "\n")
        self.assertEqual(read(os.path.join(pp, "results.md")), "results\n")


if __name__ == "__main__":
    unittest.main()

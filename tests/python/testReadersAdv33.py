"""What the independent pass adv33 found in the Python readers and scripts
(fix19l), on small synthetic files: a damaged number named by file, line
and column (sh25, c13); segments of a continued run with another header
not joined (b14, b08); our logs checked to reach the latest committed time
(pb07); no relative error against a reference at rest (pw01); the
scripts' one-line errors (neuronFsi.script)."""
import os
import subprocess
import sys
import unittest

from fixtures import TempDirTestCase
from neuronFsi import planeWave, postProcessing as pp, script

PROBES = ("# Probe 0 (0 0 1e-05)\n# Probe 1 (0 %s 0)\n#  Probe 0 1\n"
          "#  Time\n")


class DamagedNumbers(TempDirTestCase):

    def testZeroBytesNamedByLineAndColumn(self):
        p = self.write("a.dat", "# x [m]  rho [kg/m^3]\n1 2\n3 4\0\0\n5 6\n")
        with self.assertRaisesRegex(
                pp.ColumnFileError, r"a.dat, line 3, column 2 \('rho'\): "
                r"'4\\0\\0' is not a number; it holds zero bytes"):
            pp.readTable(p).data()

    def testWordNamed(self):
        p = self.write("a.dat", "# x [m]  rho [kg/m^3]\n1 2\n3 x4\n5 6\n")
        with self.assertRaisesRegex(pp.ColumnFileError,
                                    r"line 3, column 2 \('rho'\): 'x4'"):
            pp.readTable(p).data()


class SegmentHeaders(TempDirTestCase):

    def testMovedProbeNotJoined(self):
        self.write("postProcessing/probes/0/p",
                   PROBES % "1e-05" + "0 1 2\n1e-9 1 2\n")
        self.write("postProcessing/probes/1e-09/p",
                   PROBES % "1.5e-05" + "1e-9 1 2\n2e-9 1 2\n")
        with self.assertRaisesRegex(
                pp.ColumnFileError, r"0/p and .*1e-09/p: the headers differ"
                r" at header line 2: '# Probe 1 \(0 1e-05 0\)' in the first,"
                r" '# Probe 1 \(0 1.5e-05 0\)' in the later"):
            pp.series(self.tmp, "probes/p", verify=False)

    def testSameHeaderJoined(self):
        for t0 in ("0", "1e-09"):
            self.write("postProcessing/probes/%s/p" % t0,
                       PROBES % "1e-05" + "%s 1 2\n" % t0)
        self.assertEqual(pp.series(self.tmp, "probes/p", verify=False).shape, (2, 3))


class Coverage(TempDirTestCase):

    def testCutLogRefused(self):
        self.write("2e-09/.writeCommitted", "2e-09\n")
        self.write("1e-09/.writeCommitted", "1e-09\n")
        data = [[0.0], [1e-9]]
        import numpy as np
        with self.assertRaisesRegex(
                pp.ColumnFileError, r"rows end at t = 1e-09 s, before the "
                r"latest time the run wrote, 2e-09 s .*: the file is cut"):
            pp.checkCovers(self.tmp, "solidInterfaces/interfaceMaxima.dat",
                           np.array(data))
        pp.checkCovers(self.tmp, "x/y.dat", np.array([[0.0], [2.1e-9]]))

    def testTimeNameRounded(self):
        # the time directory's name is the time to its digits: a log whose
        # last row is the exact time covers it (blast.axisymmetricPreview
        # Smoke: 2.200335068e-08 s in 2.2003351e-08); one a step short not
        import numpy as np
        self.write("2.2003351e-08/.writeCommitted", "\n")
        pp.checkCovers(self.tmp, "x/y.dat",
                       np.array([[0.0], [2.200335068e-08]]))
        with self.assertRaises(pp.ColumnFileError):
            pp.checkCovers(self.tmp, "x/y.dat",
                           np.array([[0.0], [2.1999e-08]]))
        with self.assertRaises(pp.ColumnFileError):
            pp.checkCovers(self.tmp, "x/y.dat",
                           np.array([[0.0], [2.2003341e-08]]))

    def testNoCommittedTime(self):
        import numpy as np
        pp.checkCovers(self.tmp, "x/y.dat", np.array([[0.0]]))


class PlaneWaveAtRest(unittest.TestCase):

    def testZeroReferenceNoError(self):
        m = {"arrival": None, "peak1ns": 1.0, "peakIncident": 0.0,
             "plateau": None, "impulse": 2.0}
        r = {"arrival": None, "peak1ns": 0.0, "peakIncident": 0.0,
             "plateau": 1.0, "impulse": 4.0}
        e = planeWave.errors(m, r)
        self.assertIsNone(e["peak1ns"])
        self.assertIsNone(e["peakIncident"])
        self.assertAlmostEqual(e["impulse"], -0.5)


class ScriptErrors(TempDirTestCase):

    def run_(self, body, env=None):
        p = self.write("s.py", "import sys\n" + body)
        return subprocess.run([sys.executable, p], capture_output=True,
                              text=True, env=env)

    def testReaderErrorOneLine(self):
        bad = self.write("a.dat", "# x [m]\n1\n2x\n3\n")
        r = self.run_("from neuronFsi import script, postProcessing\n"
                      "script.guard()\n"
                      "postProcessing.readTable(%r).data()\n" % bad)
        self.assertEqual(r.returncode, 1)
        self.assertNotIn("Traceback", r.stderr)
        self.assertRegex(r.stderr, r"^s.py: error: .*a.dat, line 3")

    def testEveryScriptUnderTheGuard(self):
        # fix19k (adv53 u12's class): every Python script of the project
        # that imports neuronFsi calls script.guard() (an input's error in
        # one line, no traceback); found by grep, 31 scripts had none
        # (checkPreview.py without its argument: IndexError, adv53 l05).
        # Not scripts: modules the calibration imports
        root = os.path.abspath(os.path.join(os.path.dirname(__file__),
                                            "..", ".."))
        modules = {"applications/utilities/calibrateCell/forwardModel.py",
                   "applications/utilities/calibrateCell/targets.py"}
        files = subprocess.run(["git", "ls-files", "*.py"], cwd=root,
                               capture_output=True, text=True).stdout.split()
        if not files:
            self.skipTest("not a git work tree")
        without = []
        for f in files:
            if f.startswith(("src/python/", "tests/python/",
                             "tests/badInput/adv")) or f in modules:
                continue
            with open(os.path.join(root, f), errors="replace") as h:
                text = h.read()
            if "neuronFsi" in text and "guard(" not in text:
                without.append(f)
        self.assertEqual(without, [])

    def testMissingProgram(self):
        r = self.run_("from neuronFsi import script\nscript.guard()\n"
                      "import subprocess\n"
                      "subprocess.run(['noSuchProgramOf19l'])\n")
        self.assertEqual(r.returncode, 1)
        self.assertIn("the program 'noSuchProgramOf19l' is not found on "
                      "PATH", r.stderr)

    def testOtherErrorKeepsTraceback(self):
        r = self.run_("from neuronFsi import script\nscript.guard()\n"
                      "1/0\n")
        self.assertIn("Traceback", r.stderr)

    def testFullDiskNamesTheFile(self):
        # adv38 x55: ENOSPC comes from write() or the flush at close, with
        # no file name: "a file could not be written or read"; the writers
        # (planeWave's tables, measures) name the file (/dev/full: every
        # write fails with ENOSPC)
        with self.assertRaises(OSError) as c:
            with script.writing("/dev/full") as f:
                f.write("x" * 100000)
        self.assertEqual(c.exception.filename, "/dev/full")
        self.assertEqual(script.message(c.exception),
                         "/dev/full: No space left on device")

    def testWritingReplacesALink(self):
        # adv44 a17: a link at an output's path was written through, the
        # user's file it points to (outside the case) overwritten
        shared = self.write("shared.md", "my shared notes\n")
        out = os.path.join(self.tmp, "results.md")
        os.symlink(shared, out)
        with script.writing(out) as f:
            f.write("results\n")
        self.assertFalse(os.path.islink(out))
        with open(out) as f:
            self.assertEqual(f.read(), "results\n")
        with open(shared) as f:
            self.assertEqual(f.read(), "my shared notes\n")

    def testFullDiskOutsideWritingNamesTheFile(self):
        # adv38 x55 (still on fix19x): a write on a full disk outside
        # script.writing names no file; the file is found from the
        # traceback (a file object open for writing)
        r = self.run_("from neuronFsi import script\nscript.guard()\n"
                      "def save(path):\n"
                      "    with open(path, 'w') as f:\n"
                      "        f.write('x' * 100000)\n"
                      "save('/dev/full')\n")
        self.assertEqual(r.returncode, 1)
        self.assertIn("/dev/full: No space left on device (", r.stderr)
        self.assertIn("bytes free on the device of '/dev')", r.stderr)
        self.assertNotIn("a file could not be written", r.stderr)

    def testFullDiskStandardOutputNamed(self):
        # adv38 x55 (still on fix19z's first version): planeWave's print to
        # its log on a full file system raised ENOSPC; the log is the
        # standard output, a regular file on a device with (here: said to
        # have) no space left
        log = os.path.join(self.tmp, "log.pw")
        body = ("import os\nfrom neuronFsi import script\nscript.guard()\n"
                "class Full:\n    f_bavail = 0\n    f_frsize = 4096\n"
                "os.fstatvfs = lambda fd: Full\n"
                "raise OSError(28, 'No space left on device')\n")
        p = self.write("s.py", body)
        with open(log, "w") as out:
            r = subprocess.run([sys.executable, p], stdout=out,
                               stderr=subprocess.PIPE, text=True)
        self.assertEqual(r.returncode, 1)
        self.assertIn("error: the standard output (%s): No space left on "
                      "device (" % log, r.stderr)
        self.assertNotIn("a file could not be written", r.stderr)

    def testMessage(self):
        self.assertIsNone(script.message(ValueError("x")))
        self.assertIn("missing.dat", script.message(
            FileNotFoundError(2, "No such file", "/a/missing.dat")))


class SolidDigest(TempDirTestCase):

    def testChangedValueRefused(self):
        import h5py
        import numpy as np
        from neuronFsi import solidResults
        p = os.path.join(self.tmp, "solid.h5")
        u = np.zeros((4, 3))
        with h5py.File(p, "w") as f:
            f["mesh/coordinates"] = u
            f["steps/0/displacement"] = u
            f["steps/0"].attrs["time"] = 0.0
            for k in ("mesh/coordinates", "steps/0/displacement"):
                f[k].attrs["digest64"] = np.uint64(solidResults.digest64(u))
        with solidResults.SolidResults(p) as r:
            self.assertEqual(r.field("0", "displacement").shape, (4, 3))
        with h5py.File(p, "a") as f:
            f["steps/0/displacement"][0, 2] = np.nan
        with solidResults.SolidResults(p) as r:
            r.mesh("coordinates")
            with self.assertRaisesRegex(
                    solidResults.SolidResultsError,
                    r"solid.h5: dataset /steps/0/displacement: its values "
                    r"do not match their digest digest64"):
                r.field("0", "displacement")


if __name__ == "__main__":
    unittest.main()

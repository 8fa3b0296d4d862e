"""neuronFsi.options: an option's value may be a negative number
(planeWave -dz -25e-9 was argparse's "expected one argument", not the
range check's message; issue 19)."""
import argparse
import os
import subprocess
import sys
import unittest

from neuronFsi import options

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))


def parser():
    p = argparse.ArgumentParser(prog="t")
    p.add_argument("-dz", type=float, default=1.0)
    p.add_argument("-values")
    p.add_argument("-check", action="store_true")
    p.add_argument("rest", nargs="*")
    return p


class NegativeValues(unittest.TestCase):

    def testNegativeNumbersAreValues(self):
        a = options.parse(parser(), ["-dz", "-25e-9", "-values", "-1 -2e3"])
        self.assertEqual(a.dz, -25e-9)
        self.assertEqual(a.values, "-1 -2e3")
        a = options.parse(parser(), ["-dz", "-.5", "-check"])
        self.assertEqual(a.dz, -0.5)
        self.assertTrue(a.check)

    def testHelpIsArgparsesHelp(self):
        # -help (OpenFOAM's spelling) prints the usage, exit 0 (adv30 sw01,
        # kh01: "ignored explicit argument 'elp'", exit 2)
        r = subprocess.run([sys.executable, "-c",
                            "import argparse; from neuronFsi import options;"
                            "p = argparse.ArgumentParser(prog='t');"
                            "p.add_argument('-dz');"
                            "options.parse(p, ['-help'])"],
                           capture_output=True, text=True,
                           env=dict(os.environ))
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIn("usage: t", r.stdout)

    def testOptionsStayOptions(self):
        # a flag before a negative positional, an option's word value
        a = options.parse(parser(), ["-check", "-values", "abc"])
        self.assertTrue(a.check)
        self.assertEqual(a.values, "abc")
        with self.assertRaises(SystemExit):
            options.parse(parser(), ["-dz", "-check"])

    def testPlaneWaveNamesTheNegativeDz(self):
        r = subprocess.run([sys.executable, os.path.join(
            ROOT, "applications/utilities/planeWave/planeWave.py"),
            "-dz", "-25e-9"], capture_output=True, text=True,
            env=dict(os.environ, PYTHONPATH=os.path.join(ROOT, "src/python")))
        self.assertEqual(r.returncode, 2, r.stderr)
        self.assertIn("-dz -2.5e-08 m: must be positive and finite", r.stderr)


class RepeatedOptions(unittest.TestCase):
    """An option given twice is a usage error naming it (argparse took the
    last silently: issue 19, pw42, op01, op02, pa20, op04)."""

    def refused(self, argv):
        r = subprocess.run([sys.executable, "-c",
                            "import argparse, sys; from neuronFsi import "
                            "options;"
                            "p = argparse.ArgumentParser(prog='t');"
                            "p.add_argument('-dz', type=float);"
                            "p.add_argument('-check', action='store_true');"
                            "p.add_argument('-output', action='append');"
                            "options.parse(p, sys.argv[1:])"] + argv,
                           capture_output=True, text=True,
                           env=dict(os.environ))
        self.assertEqual(r.returncode, 2, r.stderr)
        self.assertNotIn("Traceback", r.stderr)
        return r.stderr

    def testValueTwice(self):
        err = self.refused(["-dz", "1", "-dz", "-2e-9"])
        self.assertIn("option -dz is given 2 times (values '1', '-2e-9'): "
                      "give it once", err)
        self.assertIn("option -dz is given 2 times",
                      self.refused(["-dz=1", "-check", "-dz", "2"]))

    def testSwitchTwice(self):
        self.assertIn("option -check is given 2 times",
                      self.refused(["-check", "-check"]))

    def testAppendedOptionsAndOnceAreValid(self):
        a = options.parse(parser(), ["-dz", "1", "-check", "-values", "dz"])
        self.assertEqual((a.dz, a.values), (1.0, "dz"))
        p = argparse.ArgumentParser(prog="t")
        p.add_argument("-output", action="append")
        self.assertEqual(options.parse(p, ["-output", "a", "-output", "b"])
                         .output, ["a", "b"])
        self.assertEqual(options.repeatedOptions(parser(), ["-dz", "1"]), [])


class NumbersOutsideTheReader(unittest.TestCase):
    """An option's number outside what OpenFOAM's reader takes (5e-324,
    1e308) is a usage error naming the option (issue 19, pv02: planeWave
    -dz 5e-324 was an OverflowError traceback), as checkOptions does for
    the C++ applications."""

    def testNamed(self):
        self.assertEqual(options.numbersOutsideReader(
            parser(), ["-dz", "5e-324", "-values", "1 2e308"]),
            [("-dz", "5e-324", "is below the smallest magnitude OpenFOAM "
              "reads (1e-300): it would be read as 0"),
             ("-values", "1 2e308", "is beyond the range of a number "
              "(OpenFOAM reads |x| <= 1e+300; a double holds |x| <= "
              "1.79769e+308)")])
        self.assertEqual(options.numbersOutsideReader(
            parser(), ["-dz=-1e-300", "-check", "1e-320"]),
            [("-dz", "-1e-300", "is below the smallest magnitude OpenFOAM "
              "reads (1e-300): it would be read as 0")])
        self.assertEqual(options.numbersOutsideReader(
            parser(), ["-dz", "2e-300", "-values", "0 1e300 abc"]), [])

    def testNotPlainNumbers(self):
        # adv46b d35: float() reads the digits of any script and '_'
        # between digits; OpenFOAM's reader does not: a usage error naming
        # the option, before anything is written
        self.assertEqual(options.numbersNotPlain(
            parser(), ["-dz", "\u0661e-\u0669", "-values", "1 2_000 3_0",
                       "-check", "\u0662"]),
            [("-dz", "\u0661e-\u0669", "\u0661e-\u0669"),
             ("-values", "1 2_000 3_0", "2_000")])
        self.assertEqual(options.numbersNotPlain(
            parser(), ["-dz", "1e-9", "-values", "caf\u00e9 1 -2e3"]), [])
        with self.assertRaises(SystemExit):
            options.parse(parser(), ["-dz", "\uff11e-6"])

    def testPlaneWaveDzDenormal(self):
        r = subprocess.run([sys.executable, os.path.join(
            ROOT, "applications/utilities/planeWave/planeWave.py"),
            "-dz", "5e-324"], capture_output=True, text=True,
            env=dict(os.environ, PYTHONPATH=os.path.join(ROOT, "src/python")))
        self.assertEqual(r.returncode, 2, r.stderr)
        self.assertIn("option -dz '5e-324': is below the smallest magnitude",
                      r.stderr)


class FileKind(unittest.TestCase):
    """options.notARegularFile: what a path is, looked at without opening
    it (a FIFO given as a file blocked the open: issue 19, adv28 m16, ir06);
    foamDict.read refuses such a path instead of blocking"""

    def setUp(self):
        import tempfile
        self.tmp = tempfile.mkdtemp(prefix="fileKind.")

    def tearDown(self):
        import shutil
        shutil.rmtree(self.tmp, ignore_errors=True)

    def testKinds(self):
        f = os.path.join(self.tmp, "file")
        with open(f, "w") as out:
            out.write("FoamFile { version 2.0; } a 1;\n")
        fifo = os.path.join(self.tmp, "fifo")
        os.mkfifo(fifo)
        self.assertEqual(options.notARegularFile(f), "")
        self.assertEqual(options.notARegularFile(self.tmp + "/none"), "")
        self.assertEqual(options.notARegularFile(self.tmp), "a directory")
        self.assertEqual(options.notARegularFile(fifo), "a FIFO (named pipe)")
        self.assertEqual(options.notARegularFile("/dev/null"), "a device")

    def testFoamDictRefusesAFifo(self):
        from neuronFsi import foamDict
        fifo = os.path.join(self.tmp, "fifo")
        os.mkfifo(fifo)
        with self.assertRaisesRegex(foamDict.DictError,
                                    "fifo is a FIFO \\(named pipe\\), not "
                                    "a file"):
            foamDict.read(fifo)


class CasePath(unittest.TestCase):

    def testBackslashNamed(self):
        # adv32 u02: OpenFOAM ran in /tmp/a/b ("cannot open root
        # directory")
        msg = options.casePathProblem("/tmp/a\\b")
        self.assertIn('holds a backslash, which OpenFOAM\'s file names '
                      'cannot hold (it would run in "/tmp/a/b")', msg)
        msg = options.casePathProblem("/tmp/a b")
        self.assertIn('holds a space, which OpenFOAM\'s file names cannot '
                      'hold (it would run in "/tmp/ab")', msg)
        self.assertEqual(options.casePathProblem("/tmp/ab"), "")


if __name__ == "__main__":
    unittest.main()

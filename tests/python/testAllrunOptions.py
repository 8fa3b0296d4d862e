"""neuronFsi.allrunOptions: the tutorials' Allrun options checked in one
place (issue 19, adv28: an option without its value looped forever, a
word or an expression was evaluated as Python code, -np abc prepared a
serial case, a re-run with other sizes kept the earlier results)."""
import json
import os
import subprocess
import sys
import unittest

from fixtures import TempDirTestCase
from neuronFsi import allrunOptions as ao
from neuronFsi import ranges

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))

DECL = """
-pulse  pulse  number(1e-10,0.9]  s
-h      h      number(0,inf)      m
-np     np     integer[1,inf)     -
-filter filter choice=yes,no      -
-inflow inflow number(0,inf)|none m
-tet    tet    flag=yes           -
-noRun  run    flag=no            -  noRecord
%results log.cellMesh
"""


def opts():
    return ao.declaration(DECL)[0]


class Parse(unittest.TestCase):

    def error(self, argv):
        with self.assertRaises(ao.OptionError) as c:
            ao.parse(opts(), argv)
        return str(c.exception)

    def testValues(self):
        g = ao.parse(opts(), ["-pulse", "5e-9", "-h", ".5e-6", "-np", "2",
                              "-filter", "yes", "-inflow", "none", "-tet",
                              "-noRun"])
        self.assertEqual(g, {"-pulse": "5e-9", "-h": ".5e-6", "-np": "2",
                             "-filter": "yes", "-inflow": "none",
                             "-tet": "yes", "-noRun": "no"})

    def testNoValueLast(self):
        self.assertEqual(self.error(["-h", "1e-6", "-pulse"]),
                         "option -pulse needs a value (valid: a number in "
                         "(1e-10, 0.9] s)")

    def testNotNumbers(self):
        # words, expressions (once evaluated as Python), nan, inf, Python's
        # own spellings that other readers do not take
        for v in ("abc", "30e-6*2", "nan", "inf", "1_0", "0x10", "", " 1",
                  "__import__('os')"):
            self.assertIn("option -h = '%s' is not a decimal number" % v,
                          self.error(["-h", v]))

    def testDigitsOfOtherScripts(self):
        # adv46b d35: Python's \d and float() take the digits of any
        # script: -endTime '\u0661e-\u0669' (Arabic-Indic) was accepted and
        # written into controlDict.allrun, refused there by the solver
        for v in ("\u0661e-\u0669", "\uff11e-6", "1e-\u0669", "\u0969"):
            self.assertIn("option -h = '%s' is not a decimal number" % v,
                          self.error(["-h", v]))
        self.assertIn("option -np = '\u0662' is not a whole number",
                      self.error(["-np", "\u0662"]))

    def testRanges(self):
        self.assertEqual(self.error(["-pulse", "0"]), "option -pulse = 0 s "
                         "is outside the valid range (1e-10, 0.9] s")
        self.assertIn("outside", self.error(["-pulse", "1e-10"]))
        self.assertEqual(ao.parse(opts(), ["-pulse", "0.9"])["-pulse"], "0.9")
        self.assertIn("outside the valid range (0, inf) m",
                      self.error(["-h", "-1e-6"]))
        self.assertIn("beyond the range of a number",
                      self.error(["-h", "1e400"]))
        self.assertIn("is not a whole number", self.error(["-np", "abc"]))
        # a whole number with an exponent or a decimal point: said so,
        # with the range (adv38 x65: "'1e9' is not a whole number")
        self.assertEqual(self.error(["-np", "2.0"]),
                         "option -np = '2.0' is written with an exponent or "
                         "a decimal point (2): write the whole number with "
                         "digits only (valid: a whole number in [1, inf))")
        self.assertIn("option -np = '1e9' is written with an exponent or a "
                      "decimal point (1000000000)", self.error(["-np", "1e9"]))
        self.assertIn("'2.5' is written with an exponent or a decimal point:"
                      " write", self.error(["-np", "2.5"]))
        self.assertIn("-np = 0 is outside the valid range [1, inf)",
                      self.error(["-np", "0"]))

    def testSolidSubcyclesRangeIsTheSolvers(self):
        # adv38 x65, adv39 y15: the preview Allrun took -solidSubcycles in
        # [1, inf), fsiProperties' coupling{} solidSubcycles [1, 1000]
        # (3000 passed the Allrun, then the solver refused it): one range
        # the solver's range: src/fsi/fsiRanges's table (fix19g), which
        # fluidSolidInteraction reads it through
        src = open(os.path.join(ROOT, "src", "fsi", "fsiRanges",
                                "fsiRanges.C")).read()
        import re
        m = re.search(r'\{"coupling", "solidSubcycles"\}, \{(\d+), (\d+), '
                      r'true, true', src)
        self.assertTrue(m)
        o = ao.allrunDeclaration(os.path.join(
            ROOT, "tutorials", "blast", "axisymmetricPreview"))
        self.assertEqual(o["-solidSubcycles"].interval,
                         "[%s, %s]" % (m.group(1), m.group(2)))
        with self.assertRaises(ao.OptionError) as c:
            ao.parse(o, ["-solidSubcycles", "3000"])
        self.assertEqual(str(c.exception), "option -solidSubcycles = 3000 "
                         "is outside the valid range [1, 1000]")

    def testBelowTheReaderRange(self):
        # adv33 ar01: -endTime 1e-301 accepted, read as 0 by OpenFOAM and
        # refused later as "-endTime 0 s"
        self.assertIn("option -h = 1e-301 m is below the smallest magnitude"
                      " OpenFOAM reads (1e-300): it would be read as 0",
                      self.error(["-h", "1e-301"]))

    def testWordsAndOptions(self):
        self.assertIn("'yess' is not valid (valid: yes or no); did you "
                      "mean 'yes'?", self.error(["-filter", "yess"]))
        self.assertIn("unknown option '-hh'; did you mean '-h'?",
                      self.error(["-hh", "1"]))
        self.assertIn("option -h given twice (1 and 2)",
                      self.error(["-h", "1", "-h", "2"]))
        self.assertIn("option -h = '-tet' is not a decimal number",
                      self.error(["-h", "-tet"]))

    def testNoOptionsDeclared(self):
        self.assertEqual(ao.parse({}, []), {})
        with self.assertRaises(ao.OptionError) as c:
            ao.parse({}, ["-endTime", "1e-9"])
        self.assertEqual(str(c.exception),
                         "takes no options (given: -endTime 1e-9)")

    def testAssignmentsAreQuoted(self):
        o = opts()
        self.assertEqual(ao.assignments(o, {"-h": "1e-6", "-tet": "yes"}),
                         "h=1e-6\ntet=yes\n")
        # a choice word with shell characters could never pass, but the
        # assignment quotes whatever it prints
        self.assertEqual(ao.assignments(o, {"-filter": "a b;$(x)"}),
                         "filter='a b;$(x)'\n")

    def testBadDeclaration(self):
        for d in ("-h h", "-h 1h number(0,inf) m", "-h h number<0,1> m",
                  "-h h number(0,1) m\n-h h number(0,1) m"):
            with self.assertRaises(ValueError):
                ao.declaration(d)


class Interval(unittest.TestCase):

    def testEnds(self):
        r = ranges.Interval("(0,1]")
        self.assertEqual(str(r), "(0, 1]")
        self.assertNotIn(0, r)
        self.assertIn(1, r)
        self.assertIn(1e-300, r)
        r = ranges.Interval("[1, inf)")
        self.assertIn(1, r)
        self.assertIn(1e300, r)
        self.assertNotIn(float("inf"), r)
        self.assertNotIn(float("nan"), ranges.Interval("(-inf, inf)"))
        for bad in ("0, 1", "(0; 1)", "(a, 1)", "<0, 1>"):
            with self.assertRaises(ValueError):
                ranges.Interval(bad)


class Calc(unittest.TestCase):

    def testValuesAreNumbers(self):
        self.assertAlmostEqual(ao.calc("cell*0.8", ["cell=1e-6"]), 8e-7)
        self.assertEqual(ao.calc("'20e-6' if Z > 30e-6 else ''",
                                 ["Z=100e-6"]), "20e-6")
        for v in ("abc", "30e-6*2", "nan", "1e400"):
            with self.assertRaises(ao.OptionError):
                ao.calc("Z*2", ["Z=" + v])


class Record(TempDirTestCase):

    def run_(self, argv):
        o, results = ao.declaration(DECL)
        cwd = os.getcwd()
        os.chdir(self.tmp)
        try:
            g = ao.parse(o, argv)
            ao.checkRecord(o, g, ".allrunOptions", results)
        finally:
            os.chdir(cwd)

    def testChangedOptionRefused(self):
        self.run_(["-h", "0.5e-6", "-noRun"])
        self.write("log.cellMesh", "")
        # the same options (another spelling of the number, without the
        # options that do not change the results): goes on
        self.run_(["-h", "5e-7"])
        with self.assertRaises(ao.OptionError) as c:
            self.run_(["-h", "0.4e-6"])
        self.assertIn("-h 0.5e-6 then, 0.4e-6 now", str(c.exception))
        self.assertIn("./Allclean", str(c.exception))
        with self.assertRaises(ao.OptionError) as c:
            self.run_(["-h", "0.5e-6", "-tet"])
        self.assertIn("-tet not given (default) then, yes now",
                      str(c.exception))
        with open(os.path.join(self.tmp, ".allrunOptions")) as f:
            self.assertEqual(json.load(f)["options"], {"-h": "0.5e-6"})

    def testResultsWithoutRecordRefused(self):
        self.write("log.cellMesh", "")
        with self.assertRaises(ao.OptionError) as c:
            self.run_([])
        self.assertIn("log.cellMesh", str(c.exception))
        self.assertFalse(os.path.exists(
            os.path.join(self.tmp, ".allrunOptions")))

    def testRecordWithoutResultsReplaced(self):
        # the earlier run stopped before its first step
        self.run_(["-h", "0.5e-6"])
        self.run_(["-h", "0.4e-6"])
        with open(os.path.join(self.tmp, ".allrunOptions")) as f:
            self.assertEqual(json.load(f)["options"], {"-h": "0.4e-6"})

    def testUnreadableRecord(self):
        self.write("log.cellMesh", "")
        self.write(".allrunOptions", "{not json")
        with self.assertRaises(ao.OptionError) as c:
            self.run_([])
        self.assertIn("not readable", str(c.exception))


class Shell(TempDirTestCase):
    """etc/RunFunctions allrunOptions in a script: the variables set, an
    error exits 1 before the script's next line."""

    def script(self, args, folder=None):
        folder = folder or self.tmp
        os.makedirs(folder, exist_ok=True)
        p = os.path.join(folder, "Allrun")
        with open(p, "w") as f:
            f.write(""". "%s/etc/RunFunctions"
h=default
allrunOptions "" "$@" <<'OPTIONS'
-h  h  number(0,inf)  m
OPTIONS
echo "h=$h"
""" % ROOT)
        return subprocess.run(["bash", p] + args, capture_output=True,
                              text=True, timeout=30, cwd=folder, env=dict(
                                  os.environ, PYTHONPATH=os.path.join(
                                      ROOT, "src/python")))

    def testCasePathWithSpace(self):
        """the case checked once, up front, in every Allrun (adv29 z4:
        foamDictionary's "stripInvalid", then "membrane = '' is not a
        finite decimal number")"""
        for name, what in (("sp ace", "a space"), ("quo'te", "'''")):
            r = self.script(["-h", "1e-6"], os.path.join(self.tmp, name))
            self.assertEqual((r.returncode, r.stdout), (1, ""))
            self.assertIn('Allrun: error: the case directory "%s" (the '
                          "Allrun's folder) holds %s, which OpenFOAM's file "
                          "names cannot hold" % (os.path.realpath(
                              os.path.join(self.tmp, name)), what),
                          r.stderr)

    def testShell(self):
        r = self.script(["-h", "1e-6"])
        self.assertEqual((r.returncode, r.stdout), (0, "h=1e-6\n"))
        r = self.script([])
        self.assertEqual((r.returncode, r.stdout), (0, "h=default\n"))
        r = self.script(["-h"])
        self.assertEqual((r.returncode, r.stdout), (1, ""))
        self.assertIn("Allrun: error: option -h needs a value", r.stderr)
        r = self.script(["-h", "$(touch x)"])
        self.assertEqual(r.returncode, 1)
        self.assertFalse(os.path.exists(os.path.join(self.tmp, "x")))


if __name__ == "__main__":
    unittest.main()

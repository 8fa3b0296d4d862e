"""sweepCase runs every value with the case as it was at the sweep's start
(adv37 w112: each value copied the case when its run started, so an edit
made during the first run reached the later runs only, the table's rows
from two different cases, without a word). The run command of the first
value edits the case itself (deterministic: one run at a time); every
run must see the case as it was, the sweep say that the case changed,
and no copy of the case be left."""
import os
import subprocess
import sys
import unittest

from fixtures import TempDirTestCase

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
SWEEP = os.path.join(ROOT, "applications", "utilities", "sweepCase",
                     "sweepCase.py")


class EditDuringTheSweep(TempDirTestCase):
    def testEveryRunSeesTheCaseOfTheStart(self):
        case = os.path.join(self.tmp, "case")
        self.write("case/system/controlDict", "application true;\n")
        self.write("case/constant/settings", "value 1;\nother a;\n")
        # each run: counts the edited entry in its copy, then edits the
        # case (the user's edit while the sweep runs)
        run = ("grep -c 'other b' constant/settings > count.txt; "
               "sed -i 's/other a/other b/' %s/constant/settings" % case)
        r = subprocess.run(
            [sys.executable, SWEEP, "-case", case,
             "-entry", "constant/settings/value", "-values", "1 2 3",
             "-run", run, "-output", r"n=count.txt:/(\d+)/"],
            capture_output=True, text=True)
        self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
        rows = [l for l in r.stdout.splitlines()
                if l.startswith("| ") and l[2].isdigit()]
        self.assertEqual(len(rows), 3, r.stdout)
        # column n: the edited entry found in the run's copy: never
        self.assertEqual([l.split("|")[2].strip() for l in rows],
                         ["0", "0", "0"], r.stdout)
        self.assertRegex(r.stdout, r"the case changed during the sweep "
                         r"\(constant/settings\)")
        self.assertFalse(os.path.exists(case + ".sweep_value_base"))


class EntryTheRunsDoNotRead(TempDirTestCase):
    """an entry the runs' copies would not read as swept is refused before
    anything runs, the user's files unchanged (adv44 a13, a36, a15)"""

    def sweep(self, entry, values="1 2"):
        return subprocess.run(
            [sys.executable, SWEEP, "-case", os.path.join(self.tmp, "case"),
             "-entry", entry, "-values", values, "-run",
             "grep -h '^value' constant/settings > out.txt",
             "-output", r"n=out.txt:/value (\d+)/"],
            capture_output=True, text=True)

    def setUp(self):
        super().setUp()
        self.write("case/system/controlDict", "application true;\n")
        self.write("case/constant/settings", "value 1;\nother a;\n")
        self.write("other/constant/settings", "value 7;\n")
        self.write("shared/settings", "value 5;\n")

    def unchanged(self):
        for name, text in (("case/constant/settings", "value 1;\nother a;\n"),
                           ("other/constant/settings", "value 7;\n"),
                           ("shared/settings", "value 5;\n")):
            with open(os.path.join(self.tmp, name)) as f:
                self.assertEqual(f.read(), text, name)
        self.assertEqual(sorted(os.listdir(self.tmp)),
                         ["case", "other", "shared"])

    def testPathThroughDotDot(self):
        r = self.sweep("../other/constant/settings/value")
        self.assertEqual(r.returncode, 1, r.stdout + r.stderr)
        self.assertIn("lies outside the case", r.stderr)
        self.assertIn("a path through '..'", r.stderr)
        self.unchanged()

    def testLinkOutside(self):
        os.symlink(os.path.join(self.tmp, "shared", "settings"),
                   os.path.join(self.tmp, "case", "constant", "linked"))
        r = self.sweep("constant/linked/value")
        self.assertEqual(r.returncode, 1, r.stdout + r.stderr)
        self.assertIn("lies outside the case", r.stderr)
        self.assertIn("through a link: it is %s" % os.path.realpath(
            os.path.join(self.tmp, "shared", "settings")), r.stderr)
        self.unchanged()

    def testValueNotOneWord(self):
        """nan, inf, a ';' or a brace in a value: refused before any run
        (adv44 a26: the values before it ran, then its run failed)"""
        for values, why in (("2 nan", "nan is not a number"),
                            ("2 3;fixed", "the value '3;fixed' holds ';'"),
                            ("2 }", "the value '}' holds '}'")):
            r = self.sweep("constant/settings/value", values)
            self.assertEqual(r.returncode, 1, r.stdout + r.stderr)
            self.assertIn(why, r.stderr)
            self.assertIn("Nothing was run", r.stderr)
            self.unchanged()

    def testSetAgainByALaterInclude(self):
        self.write("case/constant/settings",
                   "value 1;\nother a;\n#sinclude \"settings.allrun\"\n")
        self.write("case/constant/settings.allrun", "value 3;\n")
        r = self.sweep("constant/settings/value")
        self.assertEqual(r.returncode, 1, r.stdout + r.stderr)
        self.assertIn("the entry 'value' of %s is set again by a file it "
                      "includes after it" % os.path.join(
                          self.tmp, "case", "constant", "settings"),
                      r.stderr)
        # the included file without the entry: the swept value is read
        self.write("case/constant/settings.allrun", "other b;\n")
        r = self.sweep("constant/settings/value")
        self.assertEqual(r.returncode, 0, r.stdout + r.stderr)


if __name__ == "__main__":
    unittest.main()

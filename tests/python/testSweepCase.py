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


class Adv44Rows(TempDirTestCase):
    """fix19za: what adv44 found in sweepCase (issue 19): an entry leaving
    the case (a13), a linked dictionary (a36), a value set again by an
    include (a15), the user's note in a run folder (a14)."""

    def sweep(self, entry, run="grep -h radius constant/props > out.txt",
              values="20e-6 25e-6", extra=()):
        return subprocess.run(
            [sys.executable, SWEEP, "-case", self.case, "-entry", entry,
             "-values", values, "-run", run,
             "-output", r"r=out.txt:/radius\s+(\S+);/"] + list(extra),
            capture_output=True, text=True)

    def setUp(self):
        super().setUp()
        self.case = os.path.join(self.tmp, "ind")
        self.write("ind/system/controlDict", "application true;\n")
        self.props = self.write("ind/constant/props", "radius 22e-6;\n")

    def testEntryOutsideTheCaseRefused(self):
        # a13: ../ind/constant/props is the case's own file from its copy
        r = self.sweep("../ind/constant/props/radius")
        self.assertEqual(r.returncode, 1, r.stdout + r.stderr)
        self.assertIn("is outside the case", r.stderr)
        self.assertIn("../ind/constant/props/radius", r.stderr)
        with open(self.props) as f:
            self.assertEqual(f.read(), "radius 22e-6;\n")
        self.assertEqual(os.listdir(self.tmp), ["ind"])

    def testLinkedFolderRefused(self):
        # a folder on the way that is a link: outside the case too
        shared = os.path.join(self.tmp, "shared")
        os.rename(os.path.join(self.case, "constant"), shared)
        os.symlink(shared, os.path.join(self.case, "constant"))
        r = self.sweep("constant/props/radius")
        self.assertEqual(r.returncode, 1, r.stdout + r.stderr)
        self.assertIn("is a symbolic link", r.stderr)
        with open(os.path.join(shared, "props")) as f:
            self.assertEqual(f.read(), "radius 22e-6;\n")

    def testLinkedDictionaryNotWrittenThrough(self):
        # a36: the swept dictionary a link to the user's shared file
        shared = os.path.join(self.tmp, "sharedProps")
        os.rename(self.props, shared)
        os.symlink(shared, self.props)
        r = self.sweep("constant/props/radius")
        self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
        with open(shared) as f:
            self.assertEqual(f.read(), "radius 22e-6;\n")
        self.assertTrue(os.path.islink(self.props))
        rows = [l.split("|")[1:3] for l in r.stdout.splitlines()
                if l.startswith("| ") and l[2].isdigit()]
        self.assertEqual([[c.strip() for c in x] for x in rows],
                         [["20e-6", "20e-6"], ["25e-6", "25e-6"]], r.stdout)

    def testValueSetAgainByAnIncludeRefused(self):
        # a15: the tutorials' '#sinclude "<dictionary>.allrun"' pattern
        with open(self.props, "a") as f:
            f.write('#sinclude "props.allrun"\n')
        self.write("ind/constant/props.allrun", "radius 22.5e-6;\n")
        r = self.sweep("constant/props/radius")
        self.assertEqual(r.returncode, 1, r.stdout + r.stderr)
        self.assertIn("props.allrun", r.stderr)
        self.assertIn("Nothing was run", r.stderr)
        self.assertEqual(sorted(os.listdir(self.tmp)), ["ind"])

    def testUsersNoteInARunFolderKept(self):
        # a14: the user saves a note into the first value's run folder
        # while it runs; the folder is kept and named, the other removed
        run = ("grep -h radius constant/props > out.txt; "
               "test -f ../ind.sweep_radius_1/constant/props || "
               "echo mine > ../ind.sweep_radius_0/notes.txt")
        r = self.sweep("constant/props/radius", run=run)
        self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
        note = os.path.join(self.tmp, "ind.sweep_radius_0", "notes.txt")
        self.assertTrue(os.path.isfile(note), r.stdout)
        self.assertIn("kept the run folder", r.stdout)
        self.assertIn("notes.txt", r.stdout)
        self.assertFalse(os.path.exists(
            os.path.join(self.tmp, "ind.sweep_radius_1")))


class ValuesOneWord(TempDirTestCase):
    """fix19z: a value that is not one word of the entry is refused before
    anything runs, the user's files unchanged (adv44 a26)"""

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

    def testValueNotAPlainNumber(self):
        """fix19d (adv46b d42): a hexadecimal number, a comma list, a
        leading '+' and zero with a minus sign were copied and run, the
        solver failing: refused before anything is copied, naming -values
        and the value; a word and plain numbers still run"""
        for values, why in (("2 0x1p-23", "'0x1p-23' is a hexadecimal"),
                            ("1e-7,2e-7", "'1e-7,2e-7' is a list joined by"
                                          " commas"),
                            ("2 +3", "'+3' is a number with a '+' sign"),
                            ("2 -0", "'-0' is zero written with a minus"),
                            ("2 -0.0e1", "'-0.0e1' is zero written with")):
            r = self.sweep("constant/settings/value", values)
            self.assertEqual(r.returncode, 1, r.stdout + r.stderr)
            self.assertIn("-values '%s'" % values, r.stderr)
            self.assertIn(why, r.stderr)
            self.assertIn("Nothing was copied or run", r.stderr)
            self.unchanged()
        r = self.sweep("constant/settings/other", "b 0")
        self.assertNotIn("Nothing was copied", r.stderr)

    def testTooManyRuns(self):
        """fix19d (adv47b f55): 10000 values were accepted and run, every
        run's folder kept to the end: above -maxRuns (default 1000)
        refused before anything is copied; -maxRuns raises it"""
        many = " ".join(str(i) for i in range(1, 1002))
        r = self.sweep("constant/settings/value", many)
        self.assertEqual(r.returncode, 1, r.stdout + r.stderr)
        self.assertIn("-values gives 1001 values, 1001 runs of the case",
                      r.stderr)
        self.assertIn("more than -maxRuns 1000", r.stderr)
        self.assertIn("Nothing was copied or run", r.stderr)
        self.unchanged()
        r = subprocess.run(
            [sys.executable, SWEEP, "-case", os.path.join(self.tmp, "case"),
             "-entry", "constant/settings/value", "-values", "1 2 3",
             "-maxRuns", "2", "-run", "true", "-output", "n=out.txt:0:b"],
            capture_output=True, text=True)
        self.assertEqual(r.returncode, 1, r.stdout + r.stderr)
        self.assertIn("more than -maxRuns 2", r.stderr)
        self.unchanged()

    def testCasePathWithASpace(self):
        """adv45 b05 (b): a space in the case path was found by the first
        run's solver, its run folder left beside the case: refused before
        anything is copied, naming the path and the character"""
        self.write("my case/system/controlDict", "application true;\n")
        self.write("my case/constant/settings", "value 1;\n")
        r = subprocess.run(
            [sys.executable, SWEEP, "-case", os.path.join(self.tmp, "my case"),
             "-entry", "constant/settings/value", "-values", "1 2", "-run",
             "true", "-output", "n=out.txt:0:b"],
            capture_output=True, text=True)
        self.assertEqual(r.returncode, 1, r.stdout + r.stderr)
        self.assertRegex(r.stderr, r"the case directory \".*/my case\" holds "
                         r"a space(.|\n)*Nothing was read or written")
        self.assertNotIn("Traceback", r.stderr)
        self.assertEqual(sorted(os.listdir(self.tmp)),
                         ["case", "my case", "other", "shared"])


if __name__ == "__main__":
    unittest.main()

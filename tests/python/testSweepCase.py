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


if __name__ == "__main__":
    unittest.main()

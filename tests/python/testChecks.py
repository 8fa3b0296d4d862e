"""neuronFsi.checks: what a test script prints per check, what it keeps of
the failures, its exit status."""
import io
import unittest
from contextlib import redirect_stdout

import numpy as np

from neuronFsi.checks import Checks


class ChecksTest(unittest.TestCase):

    def run_checks(self, *calls):
        check = Checks()
        shown = io.StringIO()
        with redirect_stdout(shown):
            results = [call(check) for call in calls]
        return check, shown.getvalue(), results

    def testPassAndFail(self):
        check, shown, results = self.run_checks(
            lambda c: c(True, "first"), lambda c: c(np.bool_(False), "second"),
            lambda c: c(None, "third: no summary"))
        self.assertEqual(shown, "ok   first\nFAIL second\n"
                         "FAIL third: no summary\n")
        self.assertEqual(results, [True, False, False])
        self.assertIs(type(results[1]), bool)
        self.assertEqual(check.failed, ["second", "third: no summary"])
        self.assertEqual(check.exitStatus(), 1)

    def testAllPassed(self):
        check, shown, _ = self.run_checks(lambda c: c(1 < 2, "a"))
        self.assertEqual((check.failed, check.exitStatus()), ([], 0))

    def testRelative(self):
        check, shown, results = self.run_checks(
            lambda c: c.relative("force", -2.000000001, -2.0, 1e-9),
            lambda c: c.relative("arrival [s]", 1.1e-8, 1e-8, 0.03))
        self.assertEqual(shown.splitlines(), [
            "ok   force: -2.000000001 vs -2 (relative 5.00e-10, "
            "tolerance 1e-09)",
            "FAIL arrival [s]: 1.1e-08 vs 1e-08 (relative 1.00e-01, "
            "tolerance 0.03)"])
        self.assertEqual(results, [True, False])
        self.assertEqual(check.failed, [shown.splitlines()[1][5:]])
        check, _, results = self.run_checks(
            lambda c: c.relative("at the tolerance", 1.5, 1.0, 0.5))
        self.assertEqual(results, [True])


if __name__ == "__main__":
    unittest.main()

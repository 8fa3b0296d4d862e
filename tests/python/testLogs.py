"""neuronFsi.logs on log excerpts in the form our solvers and
/usr/bin/time -v write them."""
import os
import unittest

from fixtures import TempDirTestCase
from neuronFsi import logs

SOLVER = """Starting time loop

FSI map check: unit pressure, fluid force (full ring, (r z 0)) (-1.2e-10 \
-2.2e-10 0) N, solid nodal force (-1.2e-10 -2.2e-10 0) N
Time = 1e-10

ExecutionTime = 0.5 s  ClockTime = 1 s

Time = 2e-10

ExecutionTime = 0.75 s  ClockTime = 2 s

FSI coupling robin: 2 steps, 5 iterations (mean 2.5, max 3), 0 steps not \
converged
End

"""

TIMEV = """\tCommand being timed: "cellBlastFoam"
\tUser time (seconds): 80.25
\tSystem time (seconds): 1.50
\tElapsed (wall clock) time (h:mm:ss or m:ss): 1:02:03.5
\tMaximum resident set size (kbytes): 123456
\tExit status: 0
"""


class Logs(TempDirTestCase):

    def testSolverLog(self):
        p = self.write("log.cellBlastFoam", SOLVER)
        self.assertEqual(logs.executionTime(p), (0.75, 2.0))
        self.assertEqual(logs.timeSteps(p), [(1e-10, 0.5, 1.0),
                                             (2e-10, 0.75, 2.0)])
        self.assertEqual(logs.lastTime(p), 2e-10)
        self.assertEqual(logs.lastLine(p, "Time ="), "Time = 2e-10")
        self.assertIsNone(logs.lastLine(p, "CPU time"))
        self.assertIsNone(logs.cpuSplit(p))
        q = self.write("log.y", "CPU time of the time loop 12.345 s: fluid "
                       "3.21 s (26 %)\n")
        self.assertEqual(logs.cpuSplit(q), "CPU time of the time loop 12.3 s:"
                         " fluid 3.2 s (26 %)")
        self.assertTrue(logs.completed(p))
        fluid, solid = logs.fsiMapCheck(p)
        self.assertEqual(fluid, [-1.2e-10, -2.2e-10, 0.0])
        self.assertEqual(solid, fluid)
        s = logs.couplingSummary(p)
        self.assertEqual((s["steps"], s["mean"], s["max"],
                          s["notConverged"]), (2, 2.5, 3, 0))
        self.assertIsNone(logs.pressureLoadCheck(p))

    def testMissingLinesAreClearErrors(self):
        p = self.write("log.x", "Time = 1\n--> FOAM FATAL ERROR: bad\n")
        self.assertFalse(logs.completed(p))
        self.assertEqual(len(logs.fatalErrors(p)), 1)
        self.assertEqual(str(logs.executionTime(p)), "(nan, nan)")
        with self.assertRaisesRegex(logs.LogError, "log.x: no FSI map"):
            logs.fsiMapCheck(p)
        with self.assertRaisesRegex(logs.LogError, "log.x: no coupling"):
            logs.couplingSummary(p)
        with self.assertRaisesRegex(logs.LogError, "absent"):
            logs.text(os.path.join(self.tmp, "absent"))

    def testTimeV(self):
        r = logs.timeV(self.write("log.time", TIMEV))
        self.assertEqual(r, dict(rss=123456, user=80.25, system=1.5,
                                 wall=3723.5, status=0))
        r = logs.timeV(self.write("log.time", TIMEV.replace(
            "\tExit status: 0\n", "")))
        self.assertIsNone(r["status"])

    def testIndentationRun(self):
        p = self.write("log.cellIndentationFoam",
                       "Solid mesh: 1234 elements\ndelta0 = 8.4e-07 m\n"
                       "Protocol done: 56 Newton iterations, CPU time 12.5 s,"
                       " wall time 13 s\n")
        self.assertEqual(logs.indentationRun(p), dict(
            delta0=8.4e-07, cpu=12.5, wall=13.0, elements=1234,
            newtonIterations=56))
        p = self.write("log.x", "1 elements\n2 Newton iterations\n"
                       "CPU time 1 s, wall time 1 s\n")
        self.assertIsNone(logs.indentationRun(p)["delta0"])

    def testCheckMesh(self):
        p = self.write("log.checkMesh", "Mesh stats\n    points: 10\n"
                       "    cells:            1234\n")
        self.assertEqual(logs.checkMeshCells(p), 1234)


if __name__ == "__main__":
    unittest.main()

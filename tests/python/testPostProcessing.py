"""neuronFsi.postProcessing on small synthetic column files: header
parsing, a cut last row, malformed rows, restart stitching."""
import unittest

import numpy as np

from fixtures import TempDirTestCase
from neuronFsi import postProcessing as pp

HEADER = ("# FSI coupling (robin)\n"
          "# time [s]  dt [s]  iterations  residual [-]  converged"
          "  interfaceForce (x y z) [N]  interfaceVelocityMax [m/s]\n")


def row(t, it=1):
    return "%g 1e-10 %d 1e-7 1 0 %g 0 0.5\n" % (t, it, t*1e9)


class ColumnFiles(TempDirTestCase):

    def testHeaderNamesAndUnits(self):
        names, units = pp.columnNames(HEADER.split("\n")[1])
        self.assertEqual(names, [
            "time", "dt", "iterations", "residual", "converged",
            "interfaceForce_x", "interfaceForce_y", "interfaceForce_z",
            "interfaceVelocityMax"])
        self.assertEqual(units, ["s", "s", "", "-", "", "N", "N", "N",
                                 "m/s"])

    def testUnitsGluedToNames(self):
        names, units = pp.columnNames(
            "# time [s]  p0[Pa] vonMises0[Pa]  pMax:membrane-cytoplasm[Pa]"
            " stage")
        self.assertEqual(names, ["time", "p0", "vonMises0",
                                 "pMax:membrane-cytoplasm", "stage"])
        self.assertEqual(units, ["s", "Pa", "Pa", "Pa", ""])

    def testUnitOfSeveralNames(self):
        # riemannError's headers: a separate unit holds for its group
        self.assertEqual(pp.columnNames(
            "# x [m]  rho rhoExact [kg/m^3]  u uExact [m/s]"),
            (["x", "rho", "rhoExact", "u", "uExact"],
             ["m", "kg/m^3", "kg/m^3", "m/s", "m/s"]))
        self.assertEqual(pp.columnNames(
            "# nCells L1rho[kg/m^3] L1u[m/s] L1p[Pa]"),
            (["nCells", "L1rho", "L1u", "L1p"], ["", "kg/m^3", "m/s", "Pa"]))

    def testUnitBeforeNameIsAnError(self):
        with self.assertRaises(pp.ColumnFileError):
            pp.columnNames("# [s] time")

    def testTable(self):
        p = self.write("postProcessing/fsi/0/coupling.dat",
                       HEADER + row(1e-10) + row(2e-10, 3))
        t = pp.readTable(p)
        self.assertEqual(t.header[0], "FSI coupling (robin)")
        self.assertEqual(t.data().shape, (2, 9))
        np.testing.assert_array_equal(t.column("iterations"), [1, 3])
        with self.assertRaisesRegex(pp.ColumnFileError, "no column 'p'"):
            t.column("p")

    def testFiniteAndIncreasing(self):
        # adv32 pl01, pl02: nan forces and times going back, named with the
        # file's line
        p = self.write("force.dat", "# time [s]  force [N]  stage\n"
                       "0.1 1e-10 A\n0.2 nan A\n0.15 2e-10 B\n")
        t = pp.readTable(p)
        self.assertTrue(np.isnan(t.column("force")[1]))
        with self.assertRaisesRegex(pp.ColumnFileError,
                                    r"force.dat, line 3: column 'force' is "
                                    r"nan, not a finite number"):
            t.column("force", finite=True)
        with self.assertRaisesRegex(pp.ColumnFileError,
                                    r"force.dat, line 4: column 'time' = "
                                    r"0.15 is not after the previous row's "
                                    r"0.2 \(line 3\)"):
            t.column("time", increasing=True)
        np.testing.assert_array_equal(t.column("time", finite=True),
                                      [0.1, 0.2, 0.15])
        with self.assertRaisesRegex(pp.ColumnFileError,
                                    r"line 2: column 'stage' is 'A', not a "
                                    r"number"):
            t.column("stage", finite=True)

    def testNamesLineAmongNotes(self):
        # solidProbes.dat: a description before the names, a note per probe
        # after them
        p = self.write("solidProbes.dat",
                       "# solid probes (element average): pressure\n"
                       "# time [s]  p0[Pa] vonMises0[Pa]\n"
                       "# probe 0 at (0 5e-06 0) m: element 7 (nucleus)\n"
                       "1e-10 2 3\n")
        t = pp.readTable(p)
        self.assertEqual(t.names, ["time", "p0", "vonMises0"])
        self.assertEqual(t.header[2][:7], "probe 0")

    def testWordColumn(self):
        p = self.write("force.dat", "# time [s]  force [N]  stage\n"
                       "0.1 1e-10 A\n0.2 2e-10 B\n")
        t = pp.readTable(p)
        self.assertEqual(t.column("stage"), ["A", "B"])
        np.testing.assert_array_equal(t.column("force"), [1e-10, 2e-10])
        with self.assertRaisesRegex(pp.ColumnFileError, "force.dat"):
            t.data()

    def testCutLastRowDropped(self):
        # fewer fields, or a complete-looking row without its newline
        for cut in ("3e-10 1e-10 2", "3e-10 1e-10 2 1e-7 1 0 0.3 0 0.4"):
            p = self.write("c.dat", HEADER + row(1e-10) + row(2e-10) + cut)
            np.testing.assert_array_equal(pp.readTable(p).data()[:, 0],
                                          [1e-10, 2e-10])

    def testClosingNote(self):
        # cellBlastFoam ends coupling.dat with a '#' summary line
        p = self.write("c.dat", HEADER + row(1e-10) + "# 1 steps\n")
        t = pp.readTable(p)
        self.assertEqual((len(t.rows), t.notes), (1, ["1 steps"]))

    def testMalformedRowIsAnError(self):
        p = self.write("c.dat", HEADER + row(1e-10) + "2e-10 1\n"
                       + row(3e-10))
        with self.assertRaisesRegex(pp.ColumnFileError, r"c.dat, line 4"):
            pp.readTable(p)

    def testEmptyFileNamesTheMissingHeader(self):
        # adv30 pp02: an empty peaks.dat; the message says there is no
        # header, not only that the column is missing
        p = self.write("peaks.dat", "")
        with self.assertRaisesRegex(pp.ColumnFileError,
                                    r"peaks.dat: no column 'label': the "
                                    r"file has no header line"):
            pp.readTable(p).column("label")

    def testZeroBytesNamed(self):
        # adv30 pp05: zero bytes inside a row
        p = self.write("c.dat", HEADER + row(1e-10) + "2e-10 1\x00\x00 1\n"
                       + row(3e-10))
        with self.assertRaisesRegex(pp.ColumnFileError,
                                    r"c.dat, line 4: .*zero bytes"):
            pp.readTable(p)

    def testMissingFile(self):
        with self.assertRaisesRegex(pp.ColumnFileError, "no .*coupling"):
            pp.series(self.tmp, "fsi/coupling.dat", verify=False)

    def testRestartStitching(self):
        # first start to 4e-10 (its last rows are redone by the restart
        # from the write at 2e-10), the second from 2e-10 cut while
        # writing, the third from 5e-10; written out of order on purpose
        self.write("postProcessing/fsi/5e-10/coupling.dat",
                   HEADER + row(6e-10, 7) + row(7e-10, 8))
        self.write("postProcessing/fsi/0/coupling.dat",
                   HEADER + "".join(row(k*1e-10, 1) for k in range(1, 5)))
        self.write("postProcessing/fsi/2e-10/coupling.dat",
                   HEADER + "".join(row(k*1e-10, 5) for k in range(3, 7))
                   + "7e-10 1e-10")
        d = pp.series(self.tmp, "fsi/coupling.dat", verify=False)
        np.testing.assert_allclose(d[:, 0], [k*1e-10 for k in range(1, 8)])
        # later segment wins on the overlap: 3-4e-10 from the second, 6e-10
        # from the third
        np.testing.assert_array_equal(d[:, 2], [1, 1, 5, 5, 5, 7, 8])
        self.assertEqual(pp.names(self.tmp, "fsi/coupling.dat")[2],
                         "iterations")
        self.assertEqual(pp.header(self.tmp, "fsi/coupling.dat")[0],
                         "FSI coupling (robin)")
        np.testing.assert_array_equal(
            pp.latest(self.tmp, "fsi/coupling.dat").data()[:, 2], [7, 8])

    def testRoundedStartTimeName(self):
        # a restart at 2.5e-10 written under "2e-10" (timePrecision 1):
        # the first row of the segment, not its name, ends the one before
        self.write("postProcessing/fsi/0/coupling.dat", HEADER + "".join(
            row(t*1e-10, 1) for t in (1, 2, 2.5, 3)))
        self.write("postProcessing/fsi/2e-10/coupling.dat", HEADER + "".join(
            row(t*1e-10, 2) for t in (3, 3.5)))
        d = pp.series(self.tmp, "fsi/coupling.dat", verify=False)
        np.testing.assert_allclose(d[:, 0]*1e10, [1, 2, 2.5, 3, 3.5])
        np.testing.assert_array_equal(d[:, 2], [1, 1, 1, 2, 2])

    def testTimeGoingBackInASegment(self):
        # a time before the previous row's, or not a number, in a segment:
        # named with file and line (fix19k, the class of adv32 pl02)
        self.write("postProcessing/fsi/0/coupling.dat", HEADER + "".join(
            row(t*1e-10, 1) for t in (1, 2, 1.5, 3)))
        with self.assertRaisesRegex(pp.ColumnFileError,
                                    r"0/coupling.dat, line 5: the time "
                                    r"\(first column\) 1.5e-10 is before "
                                    r"the previous row's 2e-10 \(line 4\)"):
            pp.series(self.tmp, "fsi/coupling.dat", verify=False)
        self.write("postProcessing/fsi/0/coupling.dat", HEADER + row(1e-10)
                   + "nan 1e-10 1 1e-7 1 0 0 0 0.5\n")
        with self.assertRaisesRegex(pp.ColumnFileError,
                                    r"line 4: the time \(first column\) is "
                                    r"nan, not a finite number"):
            pp.series(self.tmp, "fsi/coupling.dat", verify=False)

    def testEmptySegmentSkipped(self):
        # a start killed before its first step wrote the header only
        self.write("postProcessing/fsi/0/coupling.dat",
                   HEADER + row(1e-10) + row(2e-10))
        self.write("postProcessing/fsi/2e-10/coupling.dat", HEADER)
        self.assertEqual(pp.series(self.tmp, "fsi/coupling.dat", verify=False).shape,
                         (2, 9))

    def testNonTimeDirectoriesIgnored(self):
        self.write("postProcessing/fsi/0/coupling.dat", HEADER + row(1e-10))
        self.write("postProcessing/fsi/old/coupling.dat", HEADER + row(9))
        self.assertEqual(pp.series(self.tmp, "fsi/coupling.dat", verify=False).shape,
                         (1, 9))

    def testProbesOfTheHeader(self):
        self.write("postProcessing/solidProbes/0/solidProbes.dat",
                   "# solid probes at points\n"
                   "# time [s]  p0[Pa]  p1[Pa]  p2[Pa]\n"
                   "# probe 0 fig10 at (5.04e-06 5.32e-06 0) m in cytoplasm:"
                   " element 295, patch of 7 elements\n"
                   "# probe 1 top at (1e-06 2e-06 3e-06) m in nucleus: "
                   "element 7, patch of 9 elements\n"
                   "# probe 2 ball at (1e-06 2e-06 0) m in nucleus: "
                   "element 7, patch of 40 elements: the mean over the "
                   "region within radius 5e-07 m of the point "
                   "(9.8e-18 m^3)\n"
                   "# probe 3 fig10x at (5.04e-06 5.32e-06 0) m in "
                   "nucleus: element 301, patch of 9 elements; pressure "
                   "and ln J across the interface with cytoplasm: element "
                   "295, weights 0.63 0.37\n"
                   "1e-10 1 2 3 4\n")
        p = pp.probes(self.tmp)
        self.assertEqual([(q["name"], q["element"], q["region"], q["patch"],
                           q["radius"]) for q in p],
                         [("fig10", 295, "cytoplasm", 7, 0),
                          ("top", 7, "nucleus", 9, 0),
                          ("ball", 7, "nucleus", 40, 5e-7),
                          ("fig10x", 301, "nucleus", 9, 0)])
        self.assertEqual([q["across"] for q in p[:3]], [None]*3)
        self.assertEqual(p[3]["across"], dict(region="cytoplasm",
                                              element=295,
                                              weights=(0.63, 0.37)))
        np.testing.assert_array_equal(p[0]["point"], [5.04e-6, 5.32e-6, 0])
        np.testing.assert_array_equal(p[1]["point"], [1e-6, 2e-6, 3e-6])
        self.write("postProcessing/fsi/0/coupling.dat", HEADER + row(1e-10))
        self.assertEqual(pp.probes(self.tmp, "fsi/coupling.dat"), [])

    def testProbesOfAVectorField(self):
        # OpenFOAM's probes of U: a vector "(x y z)" per probe and row,
        # read as its components (planeWave.column takes U's y)
        self.write("postProcessing/probes/0/U",
                   "# Probe 0 (0 1e-06 0)\n# Probe 1 (0 2e-06 0)\n"
                   "#      Probe        0        1\n#       Time\n"
                   "  1.2e-13   (0 0 0)   (0 0 0)\n"
                   "  2e-11   (1e-17 -32.5 0)   (0 -1.5e-3 2)\n")
        d = pp.series(self.tmp, "probes/U", vectors=True, verify=False)
        np.testing.assert_array_equal(d, [[1.2e-13, 0, 0, 0, 0, 0, 0],
                                          [2e-11, 1e-17, -32.5, 0, 0,
                                           -1.5e-3, 2]])
        with self.assertRaisesRegex(pp.ColumnFileError, "not a number"):
            pp.series(self.tmp, "probes/U", verify=False)

    def testMaterialsWithTheirBranches(self):
        p = self.write("materials.dat", "# region  rho0 [kg/m^3]  C10 [Pa]  "
                       "d0 [1/Pa]  then muN [Pa]  tauN [s]\n"
                       "nucleus 1000 6.6699999999999999 0 431.12 0.5\n"
                       "membrane 1000 166.67 1e-3 13.89 3000 1 2\n\n")
        self.assertEqual(pp.materials(p), {
            "nucleus": {"C10": 6.67, "d0": 0.0, "mu1": 431.12, "tau1": 0.5},
            "membrane": {"C10": 166.67, "d0": 1e-3, "mu1": 13.89,
                         "tau1": 3000.0, "mu2": 1.0, "tau2": 2.0}})
        with self.assertRaisesRegex(pp.ColumnFileError,
                                    r"b.dat: malformed line 'solid 1 2 3 4'"):
            pp.materials(self.write("b.dat", "solid 1 2 3 4\n"))
        with self.assertRaisesRegex(pp.ColumnFileError, "e.dat: no material"):
            pp.materials(self.write("e.dat", "# nothing\n"))
        with self.assertRaisesRegex(pp.ColumnFileError, "absent.dat"):
            pp.materials(self.tmp + "/absent.dat")


if __name__ == "__main__":
    unittest.main()

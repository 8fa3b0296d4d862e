"""neuronFsi.planeWave on synthetic histories with known answers: the
pulse's shape, the 1-ns running mean, the four measures and their errors
(the 1D column run itself is tested by tests/blast/planeWave.sh)."""
import os
import unittest

import numpy as np

from fixtures import TempDirTestCase
from neuronFsi import planeWave as pw

TABLE = [(0, 0), (1e-10, 5e7), (5e-9, 5e7), (5.1e-9, 0), (1, 0)]


def trapezoid(t, t0, rise, width, amp):
    """A pulse arriving at t0: linear rise, plateau, linear fall."""
    return amp*np.clip(np.minimum((t - t0)/rise, (t0 + width - t)/rise + 1),
                       0, 1)


class PulseShape(TempDirTestCase):

    def testAmplitudeAndHalfWidth(self):
        amp, T = pw.pulseShape(TABLE)
        self.assertEqual(amp, 5e7)
        # half-amplitude crossings at 0.05 ns and 5.05 ns
        self.assertAlmostEqual(T, 5e-9, delta=1e-20)

    def testAppliedPressureReadsTheTopTable(self):
        self.write("0.orig/p",
                   "internalField uniform 0;\nboundaryField\n{\n"
                   "    top { type uniformFixedValue; uniformValue "
                   "table ((0 0) (1e-10 5e7) (5e-09 5e7) (5.1e-09 0)"
                   " (1 0)); }\n    bottom { type zeroGradient; }\n}\n")
        self.assertEqual(pw.appliedPressure(self.tmp),
                         [(float(a), float(b)) for a, b in TABLE])
        with self.assertRaisesRegex(pw.PlaneWaveError,
                                    "boundaryField/bottom has no "
                                    "uniformValue table"):
            pw.appliedPressure(self.tmp, "bottom")


class ReferenceFile(TempDirTestCase):

    def testWrittenHeightsAndValuesReadBack(self):
        heights = [5.3193428690369811e-06, 1e-05]
        t = np.array([0.0, 1e-10, 2e-10])
        p = np.array([[0.0, 1.0], [2.5e7, 3.0], [5e7, 0.25]])
        path = self.tmp + "/reference.dat"
        pw.writeReference(path, pw.PlaneWave(heights, t, p, 25e-9, 1e-4),
                          "test")
        back = pw.readReference(path)
        np.testing.assert_array_equal(back.heights, heights)
        np.testing.assert_array_equal(back.t, t)
        np.testing.assert_array_equal(back.at(heights[0]), p[:, 0])
        with self.assertRaisesRegex(pw.PlaneWaveError, "not computed"):
            back.at(2e-5)


    def testDensitiesReadBackAndOldFilesHaveNone(self):
        heights = [1e-6, 2e-6]
        t = np.array([0.0, 1e-10])
        p = np.array([[0.0, 1.0], [2.5e7, 3.0]])
        rho = np.array([[1000.0, 1000.0], [1016.5, 1000.1]])
        path = self.tmp + "/reference.dat"
        pw.writeReference(path, pw.PlaneWave(heights, t, p, 25e-9, 1e-4,
                                             rho), "test")
        back = pw.readReference(path)
        np.testing.assert_array_equal(back.at(heights[1]), p[:, 1])
        np.testing.assert_array_equal(back.densityAt(heights[0]), rho[:, 0])
        pw.writeReference(path, pw.PlaneWave(heights, t, p, 25e-9, 1e-4),
                          "without densities")
        with self.assertRaisesRegex(pw.PlaneWaveError, "no densities"):
            pw.readReference(path).densityAt(heights[0])
        self.write("bad.dat", "# x\n# time  p_z1e-06 rho_z2e-06\n0 1 2\n")
        with self.assertRaisesRegex(pw.PlaneWaveError, "are not p_z"):
            pw.readReference(self.tmp + "/bad.dat")


class UniaxialResponse(unittest.TestCase):
    """The exact solid response to a density history: closed forms."""

    def testElasticClosedForm(self):
        t = np.linspace(0, 1e-8, 11)
        rho = 1000/np.linspace(1, 0.97, 11)         # lambda 1 -> 0.97
        ez, vm = pw.uniaxialResponse(t, rho, 1000, 3.34, [(107.78, 1e3)])
        lam = np.linspace(1, 0.97, 11)
        np.testing.assert_allclose(ez, np.log(lam), rtol=1e-12)
        # von Mises = mu |lambda^2 - 1| / lambda^(5/3), mu = mu0 + mu1
        np.testing.assert_allclose(
            vm, (3.34 + 107.78)*np.abs(lam**2 - 1)/lam**(5/3), rtol=1e-9,
            atol=1e-12)
        # about 2 mu |strain| for small strains: 6.7 Pa at 3 %
        self.assertAlmostEqual(vm[-1]/(2*111.12*abs(ez[-1])), 1, delta=0.03)

    def testMaxwellBranchRelaxesAfterAStep(self):
        tau = 1e-9
        t = np.linspace(0, 5e-9, 5001)
        lam = np.where(t > 0, 0.98, 1.0)            # strain step at t = 0+
        _, vm = pw.uniaxialResponse(t, 1000/lam, 1000, 0.0, [(100.0, tau)])
        s = abs(0.98**2 - 1)/0.98**(5/3)
        np.testing.assert_allclose(vm[1:], 100*s*np.exp(-(t[1:] - t[1])/tau)
                                   *np.exp(-0.5*(t[1] - t[0])/tau),
                                   rtol=1e-9)


class SolidMeasures(unittest.TestCase):

    def testAgainstItselfAndTheRestWindow(self):
        t = np.linspace(0, 1.5e-7, 3001)
        ez = -0.02*np.exp(-((t - 6e-8)/2e-9)**2)
        vm = 5.0*np.abs(ez)/0.02
        s, r = pw.solidMeasures(t, vm, ez, t, vm, ez)
        self.assertEqual(s, r)
        self.assertAlmostEqual(s["vonMises1ns"], 5.0, delta=0.3)
        self.assertAlmostEqual(s["strain1ns"], -0.02, delta=0.0012)
        self.assertLess(s["restStrain"], 1e-12)
        # a residual strain after the pulse is seen; a run ending before
        # the rest window has none
        s, _ = pw.solidMeasures(t, vm, ez + 0.006*(t > 8e-8), t, vm, ez)
        self.assertAlmostEqual(s["restStrain"], 0.006, delta=1e-12)
        short = t < 1.2e-7
        s, _ = pw.solidMeasures(t[short], vm[short], ez[short], t, vm, ez)
        self.assertIsNone(s["restStrain"])


class RunningMean(unittest.TestCase):

    def testExactForPiecewiseLinear(self):
        # uneven samples of a piecewise linear p: the window mean is exact
        t = np.sort(np.concatenate(([0, 10e-9], np.random.RandomState(1)
                                    .uniform(0, 10e-9, 300))))
        p = trapezoid(t, 2e-9, 1e-9, 4e-9, 3.0)
        tc, m = pw.runningMean(t, p, 1e-9)
        # at the plateau's middle the mean is the plateau; on the rise
        # centred at 2.5 ns (window 2-3 ns) it is the mean of 0..3: 1.5
        self.assertAlmostEqual(np.interp(4.5e-9, tc, m), 3.0, places=12)
        k = np.argmin(abs(tc - 2.5e-9))
        # elsewhere: the mean of the samples' linear interpolant
        fine = np.linspace(tc[k] - 0.5e-9, tc[k] + 0.5e-9, 2000001)
        exact = np.trapz(np.interp(fine, t, p), fine)/1e-9
        self.assertAlmostEqual(m[k], exact, places=9)
        self.assertTrue(tc[0] >= 0.5e-9 and tc[-1] <= 9.5e-9)


class Measures(unittest.TestCase):

    def setUp(self):
        self.t = np.linspace(0, 100e-9, 20001)
        # incident pulse at 40 ns, its echo 2 z / c later (z = 6 um)
        self.z, self.c = 6e-6, 1500.0
        echo = 2*self.z/self.c
        self.ref = (trapezoid(self.t, 40e-9, 0.1e-9, 5e-9, 5e7)
                    + trapezoid(self.t, 40e-9 + echo, 0.1e-9, 5e-9, 5e7))

    def measure(self, p):
        return pw.measures(self.t, p, self.t, self.ref, 5e7, 5e-9, self.z,
                           c0=self.c)

    def testReferenceAgainstItself(self):
        s, r = self.measure(self.ref)
        self.assertAlmostEqual(r["arrival"], 40.05e-9, delta=1e-15)
        self.assertAlmostEqual(r["plateau"], 5e7, delta=1e-3)
        self.assertAlmostEqual(r["peak1ns"], 5e7, delta=1e-3)
        self.assertAlmostEqual(r["peakIncident"], 5e7, delta=1e-3)
        # two pulses of 5 ns (ramps included: 5.1 - 0.1) x 50 MPa
        self.assertAlmostEqual(r["impulse"], 2*5e7*5e-9, delta=1e-9)
        e = pw.errors(s, r)
        self.assertEqual(e, {"arrival": 0.0, "peak1ns": 0.0,
                             "peakIncident": 0.0, "plateau": 0.0,
                             "impulse": 0.0})

    def testDelayedAndDiffusedScene(self):
        # late by 0.2 ns and 10 % low: the errors say so
        late = 0.9*np.interp(self.t - 0.2e-9, self.t, self.ref)
        e = pw.errors(*self.measure(late))
        self.assertAlmostEqual(e["arrival"], 0.2e-9 + 0.1e-9*(1/0.9 - 1)
                               * 0.5, delta=2e-12)
        for k in ("peak1ns", "peakIncident", "plateau", "impulse"):
            self.assertAlmostEqual(e[k], -0.1, delta=1e-6, msg=k)

    def testIncidentPeakLeavesTheEchoOut(self):
        # a pulse longer than the echo delay: incident and echo overlap
        # (100 MPa) at the probe; an echo 20 % high moves peak1ns, not the
        # incident peak
        t, z, c = self.t, 3e-6, self.c
        echo = 2*z/c
        inc = trapezoid(t, 40e-9, 0.1e-9, 10e-9, 5e7)
        ref = inc + trapezoid(t, 40e-9 + echo, 0.1e-9, 10e-9, 5e7)
        scene = inc + 1.2*trapezoid(t, 40e-9 + echo, 0.1e-9, 10e-9, 5e7)
        s, r = pw.measures(t, scene, t, ref, 5e7, 10e-9, z, c0=c)
        self.assertAlmostEqual(r["peak1ns"], 1e8, delta=1)
        self.assertAlmostEqual(r["peakIncident"], 5e7, delta=1)
        e = pw.errors(s, r)
        self.assertAlmostEqual(e["peak1ns"], 0.1, delta=1e-9)
        self.assertAlmostEqual(e["peakIncident"], 0.0, delta=1e-12)

    def testNoPlateauWhenTheEchoComesFirst(self):
        # probe 0.5 um above the wall: echo after 0.67 ns, no plateau
        s, r = pw.measures(self.t, self.ref, self.t, self.ref, 5e7, 5e-9,
                           0.5e-6, c0=self.c)
        self.assertIsNone(r["plateau"])
        self.assertIsNone(pw.errors(s, r)["plateau"])

    def testNoArrivalIsAnError(self):
        with self.assertRaisesRegex(pw.PlaneWaveError, "never reaches"):
            pw.measures(self.t, self.ref, self.t, 0*self.ref, 5e7, 5e-9,
                        self.z)


if __name__ == "__main__":
    unittest.main()


class ColumnRefusesBeforeRunning(TempDirTestCase):
    """column() refuses a column it cannot run in reasonable time, or bad
    sizes, before it writes or runs anything (planeWave -dz 1e-11 ran
    blockMesh on 1e7 cells and was killed; -endTime nan failed inside
    blockMesh; issue 19)"""

    def testTooManyCellsNaNAndNegative(self):
        case = self.tmp
        for kw, msg in (
                (dict(Z=100e-6, endTime=1e-7, dz=1e-11), "above the limit"),
                (dict(Z=100e-6, endTime=float("nan"), dz=50e-9),
                 "end time"),
                (dict(Z=100e-6, endTime=1e-7, dz=-5e-8), "positive"),
                (dict(Z=float("inf"), endTime=1e-7, dz=5e-8), "positive")):
            with self.assertRaisesRegex(pw.PlaneWaveError, msg):
                pw.column(case, [50e-6], **kw)
        self.assertEqual(os.listdir(case), [])
        # the limit is an argument
        with self.assertRaisesRegex(pw.PlaneWaveError, "above the limit"):
            pw.column(case, [50e-6], 100e-6, 1e-7, dz=50e-9, maxCells=1000)

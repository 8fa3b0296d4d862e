"""neuronFsi.convergence: the three-level observed order and Richardson
value (Celik et al. 2008) on exact power laws, on Celik et al.'s own worked
example, and its three kinds; bad levels refused."""
import math
import random
import unittest

from neuronFsi import convergence


class ThreeLevel(unittest.TestCase):

    def testPowerLawOnUnevenRatios(self):
        for p, h in ((1.7, (0.1, 0.2, 0.35)), (1.0, (0.125, 0.175, 0.25)),
                     (3.9, (0.3, 0.5, 0.55)), (0.3, (1.0, 2.0, 8.0))):
            f = [3.0 - 2.0*x**p for x in h]
            c = convergence.threeLevel(h, f)
            self.assertEqual(c.kind, "monotone", (p, h))
            self.assertAlmostEqual(c.p, p, delta=1e-9*p)
            self.assertAlmostEqual(c.extrapolated, 3.0, delta=1e-12)
            r = (h[1]/h[0])**p
            self.assertAlmostEqual(
                c.gci, 1.25*abs((f[1] - f[0])/f[0])/(r - 1), delta=1e-12)

    def testRatioTwoIsLog2OfTheChanges(self):
        f = (10.0, 10.4, 11.9)           # fine to coarse, h = 1, 2, 4
        c = convergence.threeLevel((1, 2, 4), f)
        self.assertAlmostEqual(c.p, math.log2(1.5/0.4), delta=1e-12)
        self.assertAlmostEqual(c.extrapolated,
                               10.0 - 0.4/(1.5/0.4 - 1), delta=1e-12)

    def testCeliksWorkedExample(self):
        # Celik et al. 2008, J. Fluids Eng. 130, 078001, Table 1, phi = 1:
        # N = 18000, 8000, 4500 cells (2D: h ~ N^-1/2), r21 = 1.5,
        # r32 = 1.333, phi = 6.063, 5.972, 5.863 -> p = 1.53,
        # phi_ext = 6.1685, GCI_fine = 2.2 %
        # (each figure to the digits the paper prints)
        h = tuple(n**-0.5 for n in (18000, 8000, 4500))
        c = convergence.threeLevel(h, (6.063, 5.972, 5.863))
        self.assertEqual(c.kind, "monotone")
        self.assertAlmostEqual(c.p, 1.53, delta=0.005)
        self.assertAlmostEqual(c.extrapolated, 6.1685, delta=0.00005)
        self.assertAlmostEqual(100*c.gci, 2.2, delta=0.05)

    def testOrderOfInputAndTheThreeFinest(self):
        h = [0.1, 0.2, 0.35, 0.5, 0.7]
        f = [1 + 0.5*x**2 for x in h]
        f[3] += 7.0                      # a coarse level far off: not used
        ref = convergence.threeLevel(h[:3], f[:3])
        idx = list(range(5))
        random.Random(4).shuffle(idx)
        c = convergence.threeLevel([h[i] for i in idx], [f[i] for i in idx])
        self.assertEqual(c, ref)
        self.assertEqual(c.h, (0.1, 0.2, 0.35))

    def testOscillatory(self):
        c = convergence.threeLevel((0.175, 0.25, 0.35), (1.0, 1.1, 0.95))
        self.assertEqual(c.kind, "oscillatory")
        self.assertIsNone(c.p)
        self.assertIsNone(c.extrapolated)
        self.assertAlmostEqual(c.halfRange, 0.075, delta=1e-15)
        self.assertAlmostEqual(c.gci, 3*0.15/1.0, delta=1e-15)

    def testDivergent(self):
        for f in ((1.0, 1.1, 1.15),      # the changes grow toward h -> 0
                  (1.0, 1.1, 1.2)):      # constant changes on ratio 2: p 0
            c = convergence.threeLevel((1, 2, 4), f)
            self.assertEqual(c.kind, "divergent", f)
            self.assertIsNone(c.p)
            self.assertIsNone(c.extrapolated)

    def testUndetermined(self):
        for f in ((1.0, 1.0, 1.2),       # a zero change
                  (1.0, 1.0 + 1e-16*3, 1.2)):   # p = log2(0.2/3e-16) > 16
            c = convergence.threeLevel((1, 2, 4), f)
            self.assertEqual(c.kind, "undetermined", f)
            self.assertIsNone(c.p)
        d = 0.2/2**15
        c = convergence.threeLevel((1, 2, 4), (1.0, 1.0 + d, 1.2 + d))
        self.assertEqual(c.kind, "monotone")      # p = 15 is an order
        self.assertAlmostEqual(c.p, 15.0, delta=1e-6)

    def testBadLevelsRefused(self):
        for h, f, msg in (((1, 2), (1, 2), "at least three"),
                          ((1, 2, 3), (1, 2), "as many sizes"),
                          ((1, 1, 3), (1, 2, 3), "distinct"),
                          ((1, -2, 3), (1, 2, 3), "positive"),
                          ((1, 2, float("nan")), (1, 2, 3), "positive"),
                          ((1, 2, 3), (1, float("inf"), 3), "finite")):
            with self.assertRaisesRegex(ValueError, msg):
                convergence.threeLevel(h, f)


if __name__ == "__main__":
    unittest.main()

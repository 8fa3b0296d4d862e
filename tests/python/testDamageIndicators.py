"""neuronFsi.damageIndicators: the deformation gradient at element centres
(exact for affine displacements, r-z hoop stretch), the Green-Lagrange
strain's principal values, interface element sets, peaks and times above a
threshold, and the series of a small case (gmsh names, solid.h5 of four
writes under a known stretch history)."""
import math
import os
import unittest

import h5py
import numpy as np

from fixtures import TempDirTestCase
from neuronFsi import damageIndicators as di, resultDigest


def rotation(a):
    c, s = math.cos(a), math.sin(a)
    return np.array([[c, -s, 0], [s, c, 0], [0, 0, 1.0]])


class Gradient(unittest.TestCase):

    def testQuadAffineRz(self):
        # a distorted quad off the axis; u_r = a r, u_z = b z + c r: F =
        # [[1+a, 0, 0], [c, 1+b, 0], [0, 0, 1+a]] exactly (hoop 1 + u_r/r)
        X = np.array([[1.0, 0.0, 0], [2.0, 0.1, 0], [2.2, 1.3, 0],
                      [0.9, 1.0, 0]])
        a, b, c = 0.01, -0.03, 0.02
        u = np.c_[a*X[:, 0], b*X[:, 1] + c*X[:, 0], np.zeros(4)]
        F = di.centreGradient(X, np.array([[0, 1, 2, 3]]), u)[0]
        np.testing.assert_allclose(
            F, [[1 + a, 0, 0], [c, 1 + b, 0], [0, 0, 1 + a]], atol=1e-14)

    def testHexAffine(self):
        rng = np.random.default_rng(1)
        X = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0],
                      [0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1.0]])
        X = X + 0.1*rng.standard_normal(X.shape)
        G = 0.05*rng.standard_normal((3, 3))
        u = X @ G.T + [1e-3, 2e-3, 0]
        F = di.centreGradient(X, np.arange(8)[None, :], u)[0]
        np.testing.assert_allclose(F, np.eye(3) + G, atol=1e-13)

    def testOtherElements(self):
        with self.assertRaisesRegex(di.IndicatorError, "elements of 3 "
                                    "nodes"):
            di.centreGradient(np.zeros((3, 3)), np.array([[0, 1, 2]]),
                              np.zeros((3, 3)))


class Strain(unittest.TestCase):

    def testPrincipal(self):
        # stretch 1.2 along a rotated axis: E1 = (1.44 - 1)/2 = 0.22, the
        # smallest (0.81 - 1)/2 = -0.095
        R = rotation(0.3)
        F = np.array([R @ np.diag([1.2, 0.9, 1.0])])
        E = di.greenLagrange(F)
        self.assertAlmostEqual(di.largestPrincipal(E)[0], 0.22, places=14)
        self.assertAlmostEqual(di.largestMagnitude(E)[0], 0.22, places=14)
        E2 = di.greenLagrange(np.array([np.diag([0.5, 1.0, 1.0])]))
        self.assertAlmostEqual(di.largestPrincipal(E2)[0], 0.0, places=14)
        self.assertAlmostEqual(di.largestMagnitude(E2)[0], 0.375,
                               places=14)


class Interface(unittest.TestCase):

    def testElements(self):
        # four quads in a row: regions 0 0 1 1; the interface is the
        # middle pair (each has a node of the other region)
        conn = np.array([[0, 1, 6, 5], [1, 2, 7, 6], [2, 3, 8, 7],
                         [3, 4, 9, 8]])
        region = np.array([0, 0, 1, 1])
        np.testing.assert_array_equal(
            di.interfaceElements(conn, region, 0, 1),
            [False, True, True, False])


class Reductions(unittest.TestCase):

    def testTimeAbove(self):
        t = [0.0, 1.0, 2.0]
        self.assertAlmostEqual(di.timeAbove(t, [0, 2, 0], 1), 1.0)
        self.assertAlmostEqual(di.timeAbove(t, [2, 2, 2], 1), 2.0)
        self.assertEqual(di.timeAbove(t, [0, 0, 0], 1), 0.0)
        self.assertAlmostEqual(di.timeAbove(t, [0, 4, 4], 1), 1.75)
        # a NaN sample: its intervals do not count
        self.assertAlmostEqual(di.timeAbove([0, 1, 2, 3],
                                            [2, math.nan, 2, 2], 1), 1.0)

    def testPeak(self):
        self.assertEqual(di.peak([1, math.nan, 3]), 3)
        self.assertTrue(math.isnan(di.peak([math.nan])))


MSH = """$MeshFormat
2.2 0 8
$EndMeshFormat
$PhysicalNames
3
1 7 "fixedBottom"
2 1 "inner"
2 2 "skin"
$EndPhysicalNames
"""


class Series(TempDirTestCase):
    """Three quads in a row, r from 1 to 4 m: regions inner, inner, skin
    (skin: a quadratic volumetric law, no temperature); u_r = a(t) r, so
    that E1 = ((1 + a)^2 - 1)/2 everywhere; writes every 1 s, window 2 s."""

    def setUp(self):
        super().setUp()
        self.write("case/constant/cell.msh", MSH)
        self.write("case/constant/solidProperties", """
mesh { type gmsh; file "constant/cell.msh"; }
materials
{
    inner { volumetric mieGruneisen; }
    skin  { volumetric quadratic; }
}
interfaces ((skin inner));
""")
        X = np.array([[1, 0, 0], [2, 0, 0], [3, 0, 0], [4, 0, 0],
                      [1, 1, 0], [2, 1, 0], [3, 1, 0], [4, 1, 0.0]])
        conn = [[0, 1, 5, 4], [1, 2, 6, 5], [2, 3, 7, 6]]
        self.a = [0.0, 0.01, 0.03, 0.02]
        os.makedirs(os.path.join(self.tmp, "case/solid"))
        with h5py.File(os.path.join(self.tmp, "case/solid/solid.h5"),
                       "w") as f:
            f["mesh/coordinates"] = X
            f["mesh/connectivity"] = conn
            f["mesh/region"] = [0, 0, 1]
            for k, a in enumerate(self.a):
                g = f.create_group("steps/%d" % k)
                g.attrs["time"] = float(k)
                u = np.c_[a*X[:, 0], np.zeros(8), np.zeros(8)]
                g["displacement"] = u
                g["pressure"] = [k, 10.0 + k, 5.0]
                g["vonMises"] = [1.0, 2.0, 3.0 + k]
                g["temperatureRise"] = [0.1*k, 0.2*k, 0.0]

    def testSeries(self):
        t, s = di.series(os.path.join(self.tmp, "case"), 2.0)
        np.testing.assert_array_equal(t, [0, 1, 2, 3])
        self.assertEqual(list(s), ["inner", "skin", "skin-inner"])
        E1 = [((1 + a)**2 - 1)/2 for a in self.a]
        for target in s:
            np.testing.assert_allclose(s[target]["strain"], E1, atol=1e-15)
            # rate over 2 s: none for the first two writes
            np.testing.assert_allclose(
                s[target]["strainRate"],
                [math.nan, math.nan, (E1[2] - E1[0])/2,
                 abs(E1[3] - E1[1])/2], atol=1e-15)
        np.testing.assert_array_equal(s["inner"]["pressure"],
                                      [10, 11, 12, 13])
        np.testing.assert_array_equal(s["skin"]["pressure"], [5]*4)
        # the interface: element 1 (inner, touching skin) and 2 (skin)
        np.testing.assert_array_equal(s["skin-inner"]["pressure"],
                                      [10, 11, 12, 13])
        np.testing.assert_array_equal(s["skin-inner"]["vonMises"],
                                      [3, 4, 5, 6])
        np.testing.assert_allclose(s["inner"]["temperatureRise"],
                                   [0, 0.2, 0.4, 0.6])
        self.assertTrue(np.isnan(s["skin"]["temperatureRise"]).all())
        np.testing.assert_allclose(s["skin-inner"]["temperatureRise"],
                                   [0, 0.2, 0.4, 0.6])

    def testWindowNotAMultiple(self):
        with self.assertRaisesRegex(di.IndicatorError,
                                    "no two writes 1.5 s apart"):
            di.series(os.path.join(self.tmp, "case"), 1.5)


class Patches(TempDirTestCase):
    """interfacePatches.dat (the solver's interface means over a fixed
    length): per interface and quantity, over a restart; its length"""

    HEAD = ("# per region interface: the largest mean over a patch of "
            "fixed size (r-z: 1e-06 m of arc along the interface; 3D: a "
            "disc of diameter 1e-06 m) of ...\n# time [s]" + "".join(
                "  " + " ".join("%s:%s[%s]" % (q, n, "m" if "Patch" in q
                                               and q[-1] in "XYZ" else "Pa")
                                for q in di.PATCH_QUANTITIES)
                for n in ("a-b", "a-fluid")) + "\n")

    def row(self, t):
        return " ".join("%g" % x for x in
                        [t] + [10*t + k for k in range(18)]) + "\n"

    def setUp(self):
        # hand-made logs (no run's digests): measured as they are
        super().setUp()
        resultDigest.measuring("-acceptHandMade", True)
        self.addCleanup(resultDigest.measuring, None, False)

    def testRead(self):
        case = os.path.join(self.tmp, "case")
        self.assertFalse(di.hasInterfacePatches(case))
        log = "case/postProcessing/solidInterfaces/%s/interfacePatches.dat"
        self.write(log % "0", self.HEAD + self.row(0) + self.row(1)
                   + self.row(2))
        # a restart from 1: its rows replace the first start's from 1 on
        self.write(log % "1", self.HEAD + self.row(1) + self.row(2)
                   + self.row(3))
        self.assertTrue(di.hasInterfacePatches(case))
        ip = di.interfacePatches(case)
        self.assertEqual(sorted(ip), ["a-b", "a-fluid"])
        np.testing.assert_array_equal(ip["a-b"]["t"], [0, 1, 2, 3])
        np.testing.assert_array_equal(ip["a-b"]["vonMisesPatch"],
                                      [1, 11, 21, 31])
        np.testing.assert_array_equal(ip["a-fluid"]["shearMax"],
                                      [17, 27, 37, 47])
        self.assertEqual(di.patchLength(case), 1e-6)


IFACES = ("a-b", "a-fluid")
PLACES = ("axis", "foot")


class Places(TempDirTestCase):
    """interfacePlaces.dat (the solver's interface means at fixed
    places): per interface, place and quantity, over a restart; the
    patches' centres from the header"""

    HEAD = ("# per region interface and fixed place: the mean over a "
            "patch of fixed size ...\n# time [s]" + "".join(
                "  " + " ".join("%s_%s:%s[Pa]" % (q, pl, n)
                                for pl in PLACES
                                for q in di.PLACE_QUANTITIES)
                for n in IFACES) + "\n" + "".join(
                "# %s:%s: point (0 2e-05 0) m, patch centre (%g 7e-06 0) "
                "m\n" % (pl, n, 1e-7*k)
                for n in IFACES for k, pl in enumerate(PLACES)))

    def row(self, t):
        return " ".join("%g" % x for x in
                        [t] + [10*t + k for k in range(12)]) + "\n"

    def setUp(self):
        # hand-made logs (no run's digests): measured as they are
        super().setUp()
        resultDigest.measuring("-acceptHandMade", True)
        self.addCleanup(resultDigest.measuring, None, False)

    def testRead(self):
        case = os.path.join(self.tmp, "case")
        self.assertFalse(di.hasInterfacePlaces(case))
        log = "case/postProcessing/solidInterfaces/%s/interfacePlaces.dat"
        self.write(log % "0", self.HEAD + self.row(0) + self.row(1)
                   + self.row(2))
        # a restart from 1: its rows replace the first start's from 1 on
        self.write(log % "1", self.HEAD + self.row(1) + self.row(2)
                   + self.row(3))
        self.assertTrue(di.hasInterfacePlaces(case))
        ip = di.interfacePlaces(case)
        self.assertEqual(sorted(ip), ["a-b", "a-fluid"])
        self.assertEqual(sorted(ip["a-b"]), ["axis", "foot"])
        np.testing.assert_array_equal(ip["a-b"]["axis"]["t"], [0, 1, 2, 3])
        # columns: a-b axis p, vM, shear; a-b foot p, vM, shear; a-fluid
        np.testing.assert_array_equal(ip["a-b"]["foot"]["vonMisesAt"],
                                      [4, 14, 24, 34])
        np.testing.assert_array_equal(ip["a-fluid"]["axis"]["shearAt"],
                                      [8, 18, 28, 38])
        self.assertEqual(ip["a-fluid"]["foot"]["centre"], (1e-7, 7e-6, 0))


if __name__ == "__main__":
    unittest.main()

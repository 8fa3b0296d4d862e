"""neuronFsi.decomposition: sectors about the cell's axis for decomposePar's
manual method."""
import os
import unittest

import numpy as np

from fixtures import TempDirTestCase
from neuronFsi import decomposition


class Sectors(unittest.TestCase):

    def testQuarterHalvesAreMirrorImages(self):
        # A quarter grid symmetric about x = y: the halves x > y and x < y
        # go to different ranks and have the same number of cells
        g = np.linspace(0.5, 9.5, 10)
        x, y, z = np.meshgrid(g, g, [1.0, 2.0], indexing="ij")
        c = np.column_stack([x.ravel(), y.ravel(), z.ravel()])
        labels = decomposition.sectors(c, 2)
        off = c[:, 0] != c[:, 1]
        np.testing.assert_array_equal(labels[off],
                                      (c[off, 1] > c[off, 0]).astype(int))
        # the diagonal's 20 cells (at the sector boundary) split evenly
        self.assertEqual(np.sum(labels == 1), np.sum(labels == 0))
        # three ranks: equal counts (200 = 67 + 67 + 66), in angular order
        labels = decomposition.sectors(c, 3)
        self.assertEqual(sorted(np.bincount(labels)), [66, 67, 67])
        theta = np.arctan2(c[:, 1], c[:, 0])
        for k in range(2):
            self.assertLessEqual(theta[labels == k].max(),
                                 theta[labels == k + 1].min())

    def testWholeTurnAndAxis(self):
        t = np.linspace(-np.pi + 0.1, np.pi - 0.1, 8)
        c = np.column_stack([np.cos(t), np.sin(t), np.zeros(8)])
        labels = decomposition.sectors(c, 4)
        np.testing.assert_array_equal(labels, [0, 0, 1, 1, 2, 2, 3, 3])
        # another axis: x; the angle in the (y, z) plane
        labels = decomposition.sectors(c[:, [2, 0, 1]], 4, axis=(1, 0, 0))
        self.assertEqual(sorted(np.bincount(labels)), [2, 2, 2, 2])
        # one sector; a cell on the axis
        np.testing.assert_array_equal(decomposition.sectors(c, 1), 0)
        np.testing.assert_array_equal(
            decomposition.sectors([[1, 1, 0], [0, 0, 1]], 2), [1, 0])

    def testBadInput(self):
        for n in (0, 1.5, -2):
            with self.assertRaisesRegex(decomposition.DecompositionError,
                                        "number of sectors"):
                decomposition.sectors([[1, 0, 0]], n)
        with self.assertRaisesRegex(decomposition.DecompositionError,
                                    "axis"):
            decomposition.sectors([[1, 0, 0]], 2, axis=(0, 0, 0))
        with self.assertRaisesRegex(decomposition.DecompositionError,
                                    "not all finite"):
            decomposition.sectors([[np.nan, 0, 0]], 2)
        with self.assertRaisesRegex(decomposition.DecompositionError,
                                    r"3 sectors for 2 cells: at most one "
                                    r"rank per cell \(valid range \[1, 2\]\)"):
            decomposition.sectors([[1, 0, 0], [0, 1, 0]], 3)
        with self.assertRaisesRegex(decomposition.DecompositionError,
                                    "m x 3"):
            decomposition.sectors(np.zeros((0, 3)), 2)


class SectorDecomposition(TempDirTestCase):

    def writeCentres(self, n):
        os.makedirs(os.path.join(self.tmp, "0"), exist_ok=True)
        t = np.linspace(0.1, 1.4, n)
        with open(os.path.join(self.tmp, "0", "C"), "w") as f:
            f.write("FoamFile { version 2.0; format ascii; class "
                    "volVectorField; object C; }\ndimensions [0 1 0 0 0 0 "
                    "0];\ninternalField nonuniform List<vector> %d\n(\n%s)"
                    ";\nboundaryField { }\n" % (n, "".join(
                        "(%g %g 0)\n" % (np.cos(a), np.sin(a)) for a in t)))

    def testAtLeastAHundredCellsPerRank(self):
        # adv pass q34: -np 4096 was accepted for any mesh
        os.makedirs(os.path.join(self.tmp, "constant"))
        self.writeCentres(250)
        self.assertEqual(list(decomposition.sectorDecomposition(self.tmp,
                                                                2)),
                         [125, 125])
        with self.assertRaisesRegex(decomposition.DecompositionError,
                                    r"3 ranks for 250 cells: fewer than 100 "
                                    r"cells per rank \(valid range \[1, 2\] "
                                    r"ranks for this mesh\)"):
            decomposition.sectorDecomposition(self.tmp, 3)

    def testNoCentres(self):
        # adv pass q46: the quarter's Allrun re-run over a decomposed case
        # (0/C removed, its step skipped): a traceback
        with self.assertRaisesRegex(decomposition.DecompositionError,
                                    r"the cell centres .*0/C cannot be read "
                                    r"\(No such file or directory\): write "
                                    r"them with postProcess"):
            decomposition.sectorDecomposition(self.tmp, 2)


class WriteManual(TempDirTestCase):

    def testLabelList(self):
        os.makedirs(os.path.join(self.tmp, "constant"))
        path = decomposition.writeManual(self.tmp, [0, 1, 1])
        with open(path) as f:
            text = f.read()
        self.assertIn("class       labelList;", text)
        self.assertTrue(text.endswith("3\n(\n0\n1\n1\n)\n"))


if __name__ == "__main__":
    unittest.main()

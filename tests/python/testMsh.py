"""neuronFsi.msh on two hand-written meshes of the same two quadrangles
(groups "nucleus" and "membrane", one boundary line "axis"): gmsh 4.1 as
cellMesh writes the cell, 2.2 as it writes the fluid box."""
import os
import unittest

from fixtures import TempDirTestCase
from neuronFsi import msh

NODES = [(1, 0, 0), (2, 1, 0), (3, 2, 0), (4, 0, 1), (5, 1, 1), (6, 2, 1)]

MSH41 = """$MeshFormat
4.1 0 8
$EndMeshFormat
$PhysicalNames
3
1 3 "axis"
2 1 "nucleus"
2 2 "membrane"
$EndPhysicalNames
$Entities
0 1 2 0
7 0 0 0 0 1 0 1 3 2 1 -4
1 0 0 0 1 1 0 1 1 0
2 1 0 0 2 1 0 1 2 0
$EndEntities
$Nodes
1 6 1 6
2 1 0 6
1
2
3
4
5
6
""" + "".join("%g %g 0\n" % (x, y) for _, x, y in NODES) + """$EndNodes
$Elements
3 3 1 3
1 7 1 1
1 1 4
2 1 3 1
2 1 2 5 4
2 2 3 1
3 2 3 6 5
$EndElements
"""

MSH22 = """$MeshFormat
2.2 0 8
$EndMeshFormat
$PhysicalNames
3
1 3 "axis"
2 1 "nucleus"
2 2 "membrane"
$EndPhysicalNames
$Nodes
6
""" + "".join("%d %g %g 0\n" % n for n in NODES) + """$EndNodes
$Elements
3
1 1 2 3 7 1 4
2 3 2 1 1 1 2 5 4
3 3 2 2 2 2 3 6 5
$EndElements
"""


class Msh(TempDirTestCase):

    def testBothFormatsAgree(self):
        for text in (MSH41, MSH22):
            X, groups = msh.read(self.write("m.msh", text))
            self.assertEqual(sorted(X), [1, 2, 3, 4, 5, 6])
            self.assertEqual(list(X[6]), [2.0, 1.0, 0.0])
            self.assertEqual(sorted(groups), ["axis", "membrane", "nucleus"])
            dim, els = groups["nucleus"]
            self.assertEqual((dim, len(els)), (2, 1))
            self.assertEqual(els[0][2:], (3, [1, 2, 5, 4]))
            self.assertEqual(groups["axis"][1][0][3], [1, 4])
            self.assertEqual(groups["membrane"][1][0][3], [2, 3, 6, 5])

    def testPhysicalNames(self):
        for text in (MSH41, MSH22):
            p = self.write("m.msh", text)
            self.assertEqual(msh.physicalNames(p, 2), ["nucleus", "membrane"])
            self.assertEqual(msh.physicalNames(p, 1), ["axis"])

    def testElementCount(self):
        for text in (MSH41, MSH22):
            p = self.write("m.msh", text)
            self.assertEqual(msh.elementCount(p, {3}), 2)
            self.assertEqual(msh.elementCount(p, {1, 3}), 3)
            self.assertEqual(msh.elementCount(p, {5}), 0)

    def testErrors(self):
        with self.assertRaisesRegex(msh.MshError, "no.msh"):
            msh.read(os.path.join(self.tmp, "no.msh"))
        p = self.write("v3.msh", MSH22.replace("2.2 0 8", "3.0 0 8"))
        with self.assertRaisesRegex(msh.MshError, "v3.msh: gmsh format 3.0"):
            msh.read(p)
        p = self.write("cut.msh", MSH22.replace("$EndElements\n", ""))
        with self.assertRaisesRegex(msh.MshError, "no \\$EndElements"):
            msh.read(p)


if __name__ == "__main__":
    unittest.main()

"""neuronFsi.cellRefinement: the quarter's water along the cell refined
(Allrun -refineCell): the distance's check and the refined mesh against
its set."""
import os

from fixtures import TempDirTestCase
from neuronFsi import cellRefinement as r

CELLMESH = """FoamFile { version 2.0; format ascii; class dictionary;
object cellMeshDict; }
mode quarter3D;
cellDiameter 16.8e-6;
cellHeight 7.9e-6;
fluid { type hex; nearSize 0.5e-6; hexCoeffs { axialSize 0.5e-6; %s } }
#sinclude "cellMeshDict.allrun"
"""

TOPOSET = """FoamFile { version 2.0; format ascii; class dictionary;
object topoSetDict; }
refineDistance 1e-6;
#sinclude "topoSetDict.allrun"
actions ( { name refineCell; type cellSet; action new;
  source surfaceToCell; nearDistance $refineDistance; } );
"""

BOUNDARY = """FoamFile { version 2.0; format ascii; class polyBoundaryMesh;
object boundary; }
2
(
    bottom
    {
        type            wall;
        nFaces          287;
        startFace       27300;
    }
    cellInterface
    {
        type            wall;
        physicalType    patch;
        nFaces          %d;
        startFace       27587;
    }
)
"""


class Distance(TempDirTestCase):

    def case(self, distance=None, margin="", fluidType="hex"):
        self.write("system/cellMeshDict", CELLMESH % margin)
        if fluidType != "hex":
            self.write("system/cellMeshDict.allrun",
                       "fluid { type %s; }\n" % fluidType)
        self.write("system/topoSetDict", TOPOSET)
        if distance is not None:
            self.write("system/topoSetDict.allrun",
                       "refineDistance %s;\n" % distance)
        return self.tmp

    def testValid(self):
        # the tracked default, an .allrun's, the default margin's bound
        # (min(a, H)/2 = 3.95 um) and a given innerMargin's
        self.assertEqual(r.readDistance(self.case()), 1e-6)
        self.assertEqual(r.readDistance(self.case("0.6e-6")), 0.6e-6)
        self.assertEqual(r.readDistance(self.case("3.95e-6")), 3.95e-6)
        self.assertEqual(r.readDistance(self.case("5e-6", "innerMargin "
                                                  "6e-6;")), 5e-6)

    def testOutsideTheRange(self):
        for bad in ("0", "-1e-6", "4e-6", "nan", "abc"):
            with self.assertRaisesRegex(
                    r.RefinementError,
                    r"system/topoSetDict: entry 'refineDistance' = \S+ m is "
                    r"outside the valid range \(0, 3\.95e-06\] m"):
                r.readDistance(self.case(bad))
        # what OpenFOAM's reader takes: 1e-400 would be read as 0
        with self.assertRaisesRegex(r.RefinementError,
                                    r"system/topoSetDict.*entry "
                                    r"'refineDistance' = 1e-400"):
            r.readDistance(self.case("1e-400"))
        with self.assertRaisesRegex(r.RefinementError,
                                    r"valid range \(0, 2e-06\] m"):
            r.readDistance(self.case("3e-6", "innerMargin 2e-6;"))

    def testMissingAndTetrahedra(self):
        self.case()
        with open(os.path.join(self.tmp, "system/topoSetDict"), "w") as f:
            f.write(TOPOSET.replace("refineDistance 1e-6;", ""))
        with self.assertRaisesRegex(r.RefinementError,
                                    "entry 'refineDistance' is missing"):
            r.readDistance(self.tmp)
        with self.assertRaisesRegex(r.RefinementError,
                                    r"cellMeshDict: entry 'fluid/type' = "
                                    r"tetrahedra.*valid: hex"):
            r.readDistance(self.case(fluidType="tetrahedra"))


class Refined(TempDirTestCase):

    def testCounts(self):
        # the quarter at -h 1e-6 -lateral 2e-6: 385 first-layer cells
        msg = r.checkRefinement(385, 9555, 12250, 385, 1540, 1e-6)
        self.assertIn("9555 -> 12250 water cells, cellInterface 385 -> "
                      "1540 faces", msg)
        with self.assertRaisesRegex(r.RefinementError,
                                    "reaches no water cell centre"):
            r.checkRefinement(0, 9555, 9555, 385, 385, 1e-7)
        # a set extended (refineHexMesh without -minSet keeps 2:1 by
        # adding cells) or cells not split
        with self.assertRaisesRegex(r.RefinementError,
                                    "9555 -> 12257 water cells, not 12250"):
            r.checkRefinement(385, 9555, 12257, 385, 1540, 1e-6)
        # a first-layer cell left out: fewer interface faces than 4x
        with self.assertRaisesRegex(r.RefinementError,
                                    "385 -> 1537 faces on cellInterface, "
                                    "not 1540"):
            r.checkRefinement(384, 9555, 12243, 385, 1537, 1e-6)

    def testFromTheCase(self):
        d = Distance.case(self, "1e-6")
        self.write("constant/polyMesh/boundary", BOUNDARY % 1540)
        self.assertEqual(r.interfaceFaces(os.path.join(
            d, "constant/polyMesh/boundary")), 1540)
        self.write("log.topoSet", "    cellSet refineCell now size 385\n")
        self.write("log.refineHexMesh",
                   "Refined from 9555 to 12250 cells.\n")
        self.assertIn("385 cells within 1e-06 m", r.checkCase(d, 385))
        with self.assertRaisesRegex(r.RefinementError, "not 1536"):
            r.checkCase(d, 384)
        os.remove(os.path.join(d, "log.refineHexMesh"))
        with self.assertRaisesRegex(r.RefinementError, "log.refineHexMesh"):
            r.checkCase(d, 385)
        self.write("constant/polyMesh/boundary", "FoamFile {}\n0 ()\n")
        with self.assertRaisesRegex(r.RefinementError,
                                    "no patch cellInterface"):
            r.interfaceFaces(os.path.join(d, "constant/polyMesh/boundary"))

"""neuronFsi.foamField on small field files in the layouts OpenFOAM
writes: ascii scalar and vector internal fields (the count on its own line
or not), ascii and binary point lists."""
import struct
import unittest

import numpy as np

from fixtures import TempDirTestCase
from neuronFsi import foamField

HEAD = """FoamFile
{
    version     2.0;
    format      %s;
    class       %s;
    object      %s;
}
"""

P = HEAD % ("ascii", "volScalarField", "p") + """\
dimensions      [1 -1 -2 0 0 0 0];

internalField   nonuniform List<scalar>
3
(
100000
1.5e+07
-2.5
)
;

boundaryField
{
    left { type zeroGradient; }
}
"""

U = HEAD % ("ascii", "volVectorField", "U") + """internalField   nonuniform \
List<vector> 2(
(1 0 0)
(0.5 -2e-09 3)
)
;
"""


class FoamField(TempDirTestCase):

    def testScalarField(self):
        p = foamField.internalField(self.write("p", P))
        np.testing.assert_array_equal(p, [1e5, 1.5e7, -2.5])

    def testVectorFieldCountOnTheListLine(self):
        u = foamField.internalField(self.write("U", U))
        np.testing.assert_array_equal(u, [[1, 0, 0], [0.5, -2e-9, 3]])

    def testNotAnAsciiList(self):
        uniform = P.replace("nonuniform List<scalar>", "uniform 0;\n//")
        with self.assertRaisesRegex(foamField.FieldError,
                                    r"/T: no ascii nonuniform internalField"):
            foamField.internalField(self.write("T", uniform))
        tensor = P.replace("List<scalar>", "List<symmTensor>")
        with self.assertRaisesRegex(foamField.FieldError,
                                    "of symmTensor: scalar or vector"):
            foamField.internalField(self.write("s", tensor))

    def testPointsAsciiAndBinary(self):
        x = [[0, 0, 0], [1e-6, 2.5e-6, -3e-6]]
        ascii = (HEAD % ("ascii", "vectorField", "points")
                 + "\n2\n(\n(0 0 0)\n(1e-06 2.5e-06 -3e-06)\n)\n")
        np.testing.assert_array_equal(
            foamField.points(self.write("a", ascii)), x)
        binary = ((HEAD % ("binary", "vectorField", "points")
                   + "\n2\n(").encode()
                  + struct.pack("<6d", *[v for q in x for v in q]) + b")\n")
        path = self.write("b", "")
        with open(path, "wb") as f:
            f.write(binary)
        np.testing.assert_array_equal(foamField.points(path), x)

    def testBinaryFields(self):
        x = [[0.25, -1e-6, 3.0], [1e-6, 2.5e-6, -3e-6], [7, 8, 9]]
        head = (HEAD % ("binary", "volVectorField", "C")
                + "dimensions [0 1 0 0 0 0 0];\n\ninternalField   "
                  "nonuniform List<vector> 3(").encode()
        body = struct.pack("<9d", *[v for q in x for v in q])
        path = self.write("C", "")
        with open(path, "wb") as f:
            f.write(head + body + b");\nboundaryField { }\n")
        np.testing.assert_array_equal(foamField.internalField(path), x)
        with open(path, "wb") as f:
            f.write(head + body[:40])
        with self.assertRaisesRegex(foamField.FieldError,
                                    r"/C: internalField cut short"):
            foamField.internalField(path)
        scalar = (HEAD % ("binary", "volScalarField", "V")
                  + "internalField nonuniform List<scalar> 2\n(").encode()
        with open(path, "wb") as f:
            f.write(scalar + struct.pack("<2d", 1.5, -2) + b");\n")
        np.testing.assert_array_equal(foamField.internalField(path),
                                      [1.5, -2])


if __name__ == "__main__":
    unittest.main()

"""neuronFsi.solidResults on a small solid.h5 in the layout of the solid
library's writer (two quads, three writes)."""
import os
import unittest

import h5py
import numpy as np

from fixtures import TempDirTestCase
from neuronFsi.solidResults import SolidResults


class Results(TempDirTestCase):

    def setUp(self):
        super().setUp()
        self.path = os.path.join(self.tmp, "solid.h5")
        with h5py.File(self.path, "w") as f:
            f["mesh/coordinates"] = np.arange(18.0).reshape(6, 3)
            f["mesh/connectivity"] = [[0, 1, 4, 3], [1, 2, 5, 4]]
            f["mesh/region"] = [0, 2]
            # keys 0, 1, 10: written in this order, sorted as text 0 1 10
            for k, t in ((0, 0.0), (1, 1e-9), (10, 2e-9)):
                g = f.create_group("steps/%d" % k)
                g.attrs["time"] = t
                g["pressure"] = [k*1.0, -k*1.0]

    def testReader(self):
        with SolidResults(self.path) as r:
            self.assertEqual(r.mesh("coordinates").shape, (6, 3))
            np.testing.assert_array_equal(r.mesh("region"), [0, 2])
            self.assertEqual(r.steps(), ["0", "1", "10"])
            self.assertEqual(r.times(), [0.0, 1e-9, 2e-9])
            self.assertEqual(r.nearest(1.4e-9), "1")
            self.assertEqual(r.nearest(5e-9), "10")
            np.testing.assert_array_equal(r.field("10", "pressure"),
                                          [10, -10])

    def testMissingFile(self):
        with self.assertRaisesRegex(OSError, "absent.h5: cannot open"):
            SolidResults(os.path.join(self.tmp, "absent.h5"))


if __name__ == "__main__":
    unittest.main()

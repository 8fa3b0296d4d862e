"""neuronFsi.solidResults on a small solid.h5 in the layout of the solid
library's writer (two quads, three writes)."""
import os
import unittest

import h5py
import numpy as np

from fixtures import TempDirTestCase
from neuronFsi.solidResults import SolidResults, SolidResultsError


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

    def testFletcherDamageNamesFileAndDataset(self):
        """a dataset whose HDF5 Fletcher-32 checksum fails (one bit of its
        chunk flipped) is a SolidResultsError naming the file and the
        dataset (adv42 g21: h5py's bare OSError named neither)"""
        from neuronFsi.solidResults import SolidResultsError
        v = np.linspace(1.0, 2.0, 64)
        with h5py.File(self.path, "a") as f:
            f.create_dataset("steps/1/velocity", data=v, chunks=(64,),
                             fletcher32=True)
        with h5py.File(self.path, "r") as f:
            at = f["steps/1/velocity"].id.get_chunk_info(0).byte_offset
        with open(self.path, "r+b") as f:
            f.seek(at + 8*10 + 3)
            b = f.read(1)[0]
            f.seek(at + 8*10 + 3)
            f.write(bytes([b ^ 0x01]))
        with SolidResults(self.path) as r:
            with self.assertRaisesRegex(
                    SolidResultsError, "solid.h5: dataset /steps/1/velocity "
                    "cannot be read: .*Fletcher32.*the file is damaged"):
                r.field("1", "velocity")

    def testMissingFile(self):
        with self.assertRaisesRegex(SolidResultsError, "absent.h5: cannot open"):
            SolidResults(os.path.join(self.tmp, "absent.h5"))


if __name__ == "__main__":
    unittest.main()

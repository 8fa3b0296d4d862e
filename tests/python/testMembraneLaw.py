"""neuronFsi.membraneLaw: the transparent cell's edit finds the blast
tutorials' membrane entry (it fails if a tutorial's solidProperties drifts
from the text it replaces) and refuses a file without it."""
import os
import shutil
import unittest

from fixtures import TempDirTestCase
from neuronFsi import membraneLaw

ROOT = os.path.normpath(os.path.join(os.path.dirname(__file__), "..", ".."))


class MembraneLaw(TempDirTestCase):

    def testBlastTutorialsGetWatersLaw(self):
        for case in ("axisymmetricPreview", "quarter3D"):
            src = os.path.join(ROOT, "tutorials", "blast", case,
                               "constant", "solidProperties")
            dst = os.path.join(self.tmp, case + ".solidProperties")
            shutil.copy(src, dst)
            membraneLaw.setWaterLaw(dst)
            with open(dst) as f:
                s = f.read()
            self.assertNotIn("volumetric  quadratic", s, case)
            # nucleus, cytoplasm and now the membrane: three water laws
            self.assertEqual(s.count("volumetric  mieGruneisen"), 3, case)
            self.assertEqual(s.count("C0 1450; s 1.99; Gamma0 0.1"), 3, case)

    def testFileWithoutTheEntryRefused(self):
        self.write("solidProperties", "materials { membrane { } }\n")
        path = os.path.join(self.tmp, "solidProperties")
        with self.assertRaisesRegex(ValueError, "found 0 times"):
            membraneLaw.setWaterLaw(path)
        with open(path) as f:
            self.assertEqual(f.read(), "materials { membrane { } }\n")


if __name__ == "__main__":
    unittest.main()

"""neuronFsi.scratch: the copy of a case's inputs leaves out what its
Allrun makes again and keeps files executable."""
import os
import unittest

from fixtures import TempDirTestCase
from neuronFsi import scratch


class Scratch(TempDirTestCase):

    def testCopyInputsLeavesOutIgnored(self):
        src = os.path.join(self.tmp, "case")
        self.write("case/Allrun", "#!/bin/sh\n")
        os.chmod(os.path.join(src, "Allrun"), 0o755)
        self.write("case/constant/solidProperties", "a 1;\n")
        self.write("case/constant/cell.msh", "mesh\n")
        self.write("case/constant/polyMesh/points", "()\n")
        self.write("case/system/controlDict", "b 2;\n")
        self.write("case/system/include/fluid.msh", "deeper\n")
        self.write("case/log.run", "not copied\n")
        dst = os.path.join(self.tmp, "copy")
        scratch.copyInputs(src, dst, ("constant", "system", "Allrun"),
                           ("*.msh", "polyMesh"))
        found = sorted(os.path.relpath(os.path.join(d, f), dst)
                       for d, _, fs in os.walk(dst) for f in fs)
        self.assertEqual(found, ["Allrun", "constant/solidProperties",
                                 "system/controlDict"])
        self.assertTrue(os.access(os.path.join(dst, "Allrun"), os.X_OK))
        with self.assertRaises(FileExistsError):
            scratch.copyInputs(src, dst, ("Allrun",))

    def testCommandLineCopiesAndRefuses(self):
        """The shell scripts' form: the same copy; an existing folder or a
        missing entry is refused before anything is copied."""
        src = os.path.join(self.tmp, "case")
        self.write("case/Allrun", "#!/bin/sh\n")
        self.write("case/constant/cell.msh", "mesh\n")
        self.write("case/constant/solidProperties", "a 1;\n")
        dst = os.path.join(self.tmp, "deeper/copy")
        scratch.main([src, dst, "constant", "Allrun", "--ignore", "*.msh"])
        found = sorted(os.path.relpath(os.path.join(d, f), dst)
                       for d, _, fs in os.walk(dst) for f in fs)
        self.assertEqual(found, ["Allrun", "constant/solidProperties"])
        with self.assertRaises(SystemExit):
            scratch.main([src, dst, "Allrun"])
        other = os.path.join(self.tmp, "other")
        with self.assertRaises(SystemExit):
            scratch.main([src, other, "Allrun", "system"])
        self.assertFalse(os.path.exists(other))


if __name__ == "__main__":
    unittest.main()

"""calibrateCell's forward model (applications/utilities/calibrateCell/
forwardModel.py): its -work folder checked before anything is written
(adv46b d24), and its runs' folders carrying every file of the case's
constant/ (adv45 c05 (c): a dictionary including "$FOAM_CASE/constant/set"
did not run in the copies)."""
import os
import sys

from fixtures import TempDirTestCase

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "applications", "utilities",
                                "calibrateCell"))
from forwardModel import ForwardModel, ModelError  # noqa: E402


class WorkFolder(TempDirTestCase):

    def testNotAFolderNamed(self):
        case = os.path.join(self.tmp, "case")
        os.makedirs(case + "/system")
        os.makedirs(case + "/constant")
        afile = self.write("afile", "mine\n")
        os.mkfifo(os.path.join(self.tmp, "fifo"))
        os.symlink(os.path.join(self.tmp, "gone"),
                   os.path.join(self.tmp, "dl"))
        for w, why in ((afile, "a file"),
                       (os.path.join(self.tmp, "fifo"), r"a FIFO \(named pipe\)"),
                       (os.path.join(self.tmp, "dl"),
                        "a symbolic link to .*gone, which is not there")):
            with self.assertRaisesRegex(ModelError, r"-work .* is %s, not a "
                                        r"folder: give -work a new or empty "
                                        r"folder" % why):
                ForwardModel(case, w)
        with open(afile) as f:
            self.assertEqual(f.read(), "mine\n")


class RunFolder(TempDirTestCase):

    def testConstantFilesCopied(self):
        m = ForwardModel.__new__(ForwardModel)
        m.work = self.tmp
        m.base = os.path.join(self.tmp, "base")
        self.write("base/system/controlDict", "endTime 1;\n")
        self.write("base/constant/cell.msh", "mesh\n")
        self.write("base/constant/solidProperties", "old\n")
        self.write("base/constant/set", "C10 1;\n")
        self.write("base/constant/more/inner", "x 1;\n")
        run = os.path.join(self.tmp, "run")
        m._make_run_dir(run, "sp\n", "ip\n")
        c = os.path.join(run, "constant")
        self.assertEqual(sorted(os.listdir(c)), ["cell.msh",
                         "indenterProperties", "more", "set",
                         "solidProperties"])
        with open(os.path.join(c, "set")) as f:
            self.assertEqual(f.read(), "C10 1;\n")
        with open(os.path.join(c, "solidProperties")) as f:
            self.assertEqual(f.read(), "sp\n")
        self.assertTrue(os.path.isfile(os.path.join(c, "more", "inner")))
        self.assertTrue(os.path.islink(os.path.join(c, "cell.msh")))


class ScratchFolder(TempDirTestCase):

    def testRefusedCaseLeavesNoTemporaryFolder(self):
        """fix19d (adv46a, adv45 c05 (a)): calibrateCell refusing a case
        before anything ran (a relative #include leaving it) left its
        temporary work folder, empty, in the temporary directory"""
        import subprocess
        root = os.path.join(os.path.dirname(os.path.abspath(__file__)),
                            "..", "..")
        case = os.path.join(self.tmp, "cal", "c")
        import shutil
        shutil.copytree(os.path.join(root, "tutorials", "calibration",
                                     "averageCell"), case)
        self.write("shared/set", "nucleus { C10 13.33; }\n")
        p = os.path.join(case, "constant", "solidProperties")
        with open(p) as f:
            text = f.read()
        with open(p, "w") as f:
            f.write(text.replace(
                '#include "$PROJECT_DIR/etc/caseDicts/cellMaterials/table"',
                '#include "../../../shared/set"'))
        tmpdir = os.path.join(self.tmp, "tmpdir")
        os.makedirs(tmpdir)
        env = dict(os.environ, TMPDIR=tmpdir)
        r = subprocess.run(
            [sys.executable, os.path.join(root, "applications", "utilities",
                                          "calibrateCell",
                                          "calibrateCell.py"),
             "-case", case, "-nProcs", "1"],
            capture_output=True, text=True, env=env)
        self.assertEqual(r.returncode, 1, r.stdout + r.stderr)
        self.assertIn("shared/set", r.stderr)
        self.assertEqual(os.listdir(tmpdir), [])

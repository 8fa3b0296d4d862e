"""neuronFsi.scratch: the copy of a case's inputs leaves out what its
Allrun makes again and keeps files executable."""
import os
import socket
import subprocess
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


class OutputFolder(TempDirTestCase):
    """adv51 n01: scripts removed a user's folder given as (or inside) their
    output folder. outputFolder uses a new or empty folder, empties only
    the script's own earlier output, refuses anything else."""

    def testNewEmptyAndOwnEarlierOutput(self):
        d = os.path.join(self.tmp, "out")
        scratch.outputFolder("s.sh", d, ("case", "*.log"))
        self.assertEqual(sorted(os.listdir(d)), sorted([scratch.MARKER, scratch.LOCK]))
        self.write("out/case/x", "1\n")
        self.write("out/run.log", "2\n")
        scratch.recordOutputs(d)        # the run's end
        scratch.outputFolder("s.sh", d, ("case", "*.log"))
        self.assertEqual(sorted(os.listdir(d)), sorted([scratch.MARKER, scratch.LOCK]))
        os.makedirs(os.path.join(self.tmp, "empty"))
        scratch.outputFolder("s.sh", os.path.join(self.tmp, "empty"))

    def testUsersFolderRefusedAndKept(self):
        self.write("user/notes.txt", "mine\n")
        self.write("user/data/run1.csv", "1\n")
        d = os.path.join(self.tmp, "user")
        with self.assertRaisesRegex(scratch.ScratchError,
                                    "holds 2 file.* that no earlier run of "
                                    r"s\.sh made there \(data notes\.txt\)"):
            scratch.outputFolder("s.sh", d)
        self.assertEqual(sorted(os.listdir(d)), ["data", "notes.txt"])
        # another script's output is not this one's
        scratch.outputFolder("t.sh", os.path.join(self.tmp, "t"))
        self.write("t/case/x", "1\n")
        with self.assertRaises(scratch.ScratchError):
            scratch.outputFolder("s.sh", os.path.join(self.tmp, "t"))
        # a user's file put into the script's own output folder
        scratch.outputFolder("s.sh", os.path.join(self.tmp, "own"), ("case",))
        self.write("own/notes.txt", "mine\n")
        with self.assertRaisesRegex(scratch.ScratchError, r"\(notes\.txt\)"):
            scratch.outputFolder("s.sh", os.path.join(self.tmp, "own"),
                                 ("case",))
        self.assertTrue(os.path.isfile(os.path.join(self.tmp, "own",
                                                    "notes.txt")))

    def testCaseEntries(self):
        """adv52 o09 (d), (b): a case folder's earlier output is emptied
        only if it holds what a run of a case leaves ("@case"), a case
        inside the folder likewise ("NAME/@case"): a user's file added
        there is refused and kept"""
        # the markers of an earlier version, without the record of what the
        # run left (judged by the entries' name patterns)
        def legacy(folder, script):
            with open(os.path.join(folder, scratch.MARKER), "w") as f:
                f.write(script + "\n")
        d = os.path.join(self.tmp, "case")
        scratch.outputFolder("run.py", d, ("@case",))
        legacy(d, "run.py")
        for f in ("system/controlDict", "0/p", "1e-09/p", "log.cellBlastFoam",
                  "postProcessing/probes/0/p", "solid/solid.h5",
                  ".allrunOptions"):
            self.write("case/" + f, "1\n")
        scratch.outputFolder("run.py", d, ("@case",))
        self.assertEqual(sorted(os.listdir(d)), sorted([scratch.MARKER, scratch.LOCK]))
        legacy(d, "run.py")
        self.write("case/system/controlDict", "1\n")
        self.write("case/analysis.txt", "mine\n")
        with self.assertRaisesRegex(scratch.ScratchError,
                                    r"\(analysis\.txt\)"):
            scratch.outputFolder("run.py", d, ("@case",))
        self.assertTrue(os.path.isfile(os.path.join(d, "analysis.txt")))
        o = os.path.join(self.tmp, "out")
        scratch.outputFolder("runPreview.sh", o, ("preview/@case",))
        legacy(o, "runPreview.sh")
        self.write("out/preview/system/controlDict", "1\n")
        self.write("out/preview/log.Allrun", "1\n")
        scratch.outputFolder("runPreview.sh", o, ("preview/@case",))
        legacy(o, "runPreview.sh")
        self.write("out/preview/system/controlDict", "1\n")
        self.write("out/preview/mine.txt", "mine\n")
        with self.assertRaisesRegex(scratch.ScratchError,
                                    r"\(preview/mine\.txt\)"):
            scratch.outputFolder("runPreview.sh", o, ("preview/@case",))
        self.assertTrue(os.path.isfile(os.path.join(o, "preview",
                                                    "mine.txt")))

    def testRunGoingOnInsideRefused(self):
        """adv52 p02 (b): a second gapStudy.sh emptied its own earlier
        folder under the first's running solver: a folder holding a live
        run lock is refused, nothing removed"""
        d = os.path.join(self.tmp, "out")
        scratch.outputFolder("g.sh", d, ("@case",))
        self.write("out/system/controlDict", "1\n")
        p = subprocess.Popen(["sleep", "60"], cwd=d)
        self.addCleanup(lambda: (p.kill(), p.wait()))
        with open(os.path.join(d, ".runLock"), "w") as f:
            f.write("pid %d\nhost %s\nexecutable sleep\nstarted now\n"
                    "case %s\n" % (p.pid, socket.gethostname(),
                                   os.path.realpath(d)))
        scratch.recordOutputs(d)        # the script ended, its solver runs
        with self.assertRaisesRegex(scratch.ScratchError,
                                    "holds a run going on .*in use by "
                                    "sleep"):
            scratch.outputFolder("g.sh", d, ("@case",))
        self.assertTrue(os.path.isfile(os.path.join(d, "system",
                                                    "controlDict")))

    def testLockOfALiveScriptRefused(self):
        """adv52 p01b (b): a folder whose lock another script holds (a
        shell script between its solver runs) is refused, nothing removed;
        a lock left by a script that ended is taken over with a note; the
        lock file this made in a user's folder it refuses goes again."""
        d = os.path.join(self.tmp, "out")
        os.makedirs(d)
        self.write("out/.scratchFolder", "s.sh\n")
        self.write("out/result.txt", "the first's\n")
        holder = subprocess.Popen(
            ["flock", "-o", os.path.join(d, ".scratchLock"), "sh", "-c",
             "printf 'pid %s\\nhost h\\n' $$ > " + os.path.join(
                 d, ".scratchLock") + "; sleep 30"])
        try:
            for _ in range(100):
                if "pid" in scratch.lockText(d):
                    break
                import time
                time.sleep(0.05)
            with self.assertRaisesRegex(
                    scratch.ScratchError,
                    r"out is in use by another script's run \(its lock "
                    r".*\.scratchLock: pid [0-9]+, host h\)"):
                scratch.outputFolder("s.sh", d, ("result.txt",))
            self.assertTrue(os.path.isfile(os.path.join(d, "result.txt")))
        finally:
            holder.kill()
            holder.wait()
        # the holder ended: its lock is taken over, the folder emptied
        scratch.outputFolder("s.sh", d, ("result.txt",))
        self.assertFalse(os.path.exists(os.path.join(d, "result.txt")))
        self.assertIn("pid %d" % os.getpid(), scratch.lockText(d))
        # a user's folder refused: no lock file left in it
        u = os.path.join(self.tmp, "user")
        self.write("user/mine.txt", "mine\n")
        with self.assertRaises(scratch.ScratchError):
            scratch.outputFolder("s.sh", u)
        self.assertEqual(os.listdir(u), ["mine.txt"])

    def testShellScriptHoldsTheLock(self):
        """etc/scratchFolder: the sourcing shell holds DIR's lock to its
        end; a second script's scratchFolder on DIR is refused meanwhile,
        exit 1, DIR's files kept."""
        root = os.path.abspath(os.path.join(os.path.dirname(__file__),
                                            "..", ".."))
        d = os.path.join(self.tmp, "sh")
        r = subprocess.run(
            ["bash", "-c", '. "$0/etc/scratchFolder"; scratchFolder a.sh '
             '"$1"; echo kept > "$1/r.txt"; bash -c \'. "$0/etc/'
             'scratchFolder"; scratchFolder a.sh "$1"\' "$0" "$1"',
             root, d], capture_output=True, text=True)
        self.assertEqual(r.returncode, 1, r.stderr)
        self.assertIn("is in use by another script's run", r.stderr)
        self.assertIn("script a.sh", r.stderr)
        self.assertTrue(os.path.isfile(os.path.join(d, "r.txt")))

    def testRecordedOutputsOnly(self):
        """adv53 u10: a folder whose marker records what the earlier run
        left is emptied only if it holds those files unchanged; a user's
        file named like a case's (logbook.txt, README.md, a figure, a file
        in postProcessing/), or a recorded file changed, is refused and
        kept. A shell script records at its end (its EXIT trap)."""
        d = os.path.join(self.tmp, "rec")
        scratch.outputFolder("r.sh", d, ("case/@case",))
        self.write("rec/case/log.run", "run\n")
        self.write("rec/case/postProcessing/probes/0/p", "1 2\n")
        scratch.recordOutputs(d)
        for name in ("case/logbook.txt", "case/README.md",
                     "case/myFigure.png", "case/postProcessing/mine.txt"):
            self.write("rec/" + name, "mine\n")
            with self.assertRaisesRegex(scratch.ScratchError,
                                        "no earlier run of r.sh made there "
                                        r"\(%s\)" % name.replace(".", r"\.")):
                scratch.outputFolder("r.sh", d, ("case/@case",))
            os.remove(os.path.join(d, name))
        self.write("rec/case/log.run", "edited by the user\n")
        with self.assertRaisesRegex(scratch.ScratchError, r"case/log\.run"):
            scratch.outputFolder("r.sh", d, ("case/@case",))
        os.remove(os.path.join(d, "case/log.run"))
        scratch.outputFolder("r.sh", d, ("case/@case",))
        self.assertEqual(sorted(os.listdir(d)),
                         sorted([scratch.MARKER, scratch.LOCK]))
        # adv53 l33: a run killed before its end left an empty record: the
        # folder holding its files is refused, not judged by name
        k = os.path.join(self.tmp, "killed")
        scratch.outputFolder("r.sh", k, ("@case",))
        self.write("killed/log.run", "run\n")
        with self.assertRaisesRegex(scratch.ScratchError, r"\(log\.run\)"):
            scratch.outputFolder("r.sh", k, ("@case",))
        self.assertTrue(os.path.isfile(os.path.join(k, "log.run")))
        root = os.path.abspath(os.path.join(os.path.dirname(__file__),
                                            "..", ".."))
        sh = os.path.join(self.tmp, "shrec")
        r = subprocess.run(
            ["bash", "-c", '. "$0/etc/scratchFolder"; scratchFolder s.sh '
             '"$1" @case; echo 1 > "$1/log.run"', root, sh],
            capture_output=True, text=True)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.write("shrec/logbook.txt", "mine\n")
        r = subprocess.run(
            ["bash", "-c", '. "$0/etc/scratchFolder"; scratchFolder s.sh '
             '"$1" @case', root, sh], capture_output=True, text=True)
        self.assertEqual(r.returncode, 1, r.stderr)
        self.assertIn("(logbook.txt)", r.stderr)
        self.assertTrue(os.path.isfile(os.path.join(sh, "log.run")))

    def testFileOrLinkRefused(self):
        self.write("f", "mine\n")
        with self.assertRaisesRegex(scratch.ScratchError, "is not a folder"):
            scratch.outputFolder("s.sh", os.path.join(self.tmp, "f"))
        os.makedirs(os.path.join(self.tmp, "real"))
        os.symlink(os.path.join(self.tmp, "real"),
                   os.path.join(self.tmp, "link"))
        with self.assertRaisesRegex(scratch.ScratchError, "is not a folder"):
            scratch.outputFolder("s.sh", os.path.join(self.tmp, "link"))

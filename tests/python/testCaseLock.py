"""The case lock of the solvers (.runLock, src/foamTools/caseLock.H) in our
Python tools (neuronFsi.caseLock): planeWave refuses a case whose run goes
on unless -partial asks for a report of the run so far (adv34 n21), and
the tools that write into a case - planeWave, planeWave -inflow, sweepCase,
calibrateCell - take the lock, refusing a live one, replacing a stale one;
their lock is one a solver's caseLock sees as live (the process's comm
name is the tool's, which begins the lock's executable)."""
import os
import shutil
import socket
import subprocess
import sys
import time
import unittest

from fixtures import TempDirTestCase
from neuronFsi import caseLock

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
UTIL = os.path.join(ROOT, "applications", "utilities")
PREVIEW = os.path.join(ROOT, "tutorials", "blast", "axisymmetricPreview")


def tool(name):
    return [sys.executable, os.path.join(UTIL, name, name + ".py")]


class LiveLockTestCase(TempDirTestCase):
    """A case (self.case) whose run lock is held by a live process of this
    host working in it (sleep, as a solver would)."""

    def setUp(self):
        super().setUp()
        self.case = os.path.join(self.tmp, "case")
        os.makedirs(self.case + "/system")

    def holdLock(self):
        p = subprocess.Popen(["sleep", "60"], cwd=self.case)
        self.addCleanup(lambda: (p.kill(), p.wait()))
        with open(self.case + "/.runLock", "w") as f:
            f.write("pid %d\nhost %s\nexecutable sleep\nstarted now\n"
                    "case %s\n" % (p.pid, socket.gethostname(),
                                   os.path.realpath(self.case)))
        return p


class PlaneWaveOnARunningCase(LiveLockTestCase):
    """adv34 n21: planeWave while the solver runs reported on the partial
    run, exit 0, without a word."""

    def testRefusedNamingTheRun(self):
        p = self.holdLock()
        self.write("case/postProcessing/fluidProbes/0/p",
                   "# Probe 0 (0 0 1e-06)\n#   Time  0\n0 1e5\n1e-9 2e5\n")
        r = subprocess.run(tool("planeWave") + ["-case", self.case],
                           capture_output=True, text=True)
        self.assertNotEqual(r.returncode, 0, r.stdout)
        self.assertRegex(r.stderr, r"planeWave: error: the case .*/case is "
                         r"not finished: it is in use by sleep \(process %d "
                         r".*Its results so far are partial.* -partial"
                         % p.pid)
        self.assertFalse(os.path.exists(self.case + "/postProcessing/"
                                        "planeWave"))
        # -partial: the run so far, said so (here it stops further on:
        # the case has no 0/p)
        r = subprocess.run(tool("planeWave") + ["-case", self.case,
                                                "-partial"],
                           capture_output=True, text=True)
        self.assertRegex(r.stdout, r"is not finished: it is in use by sleep"
                         r" .*-partial: the report is of the run so far")
        self.assertIn("no 0/p", r.stderr)


class ToolsTakeTheLock(LiveLockTestCase):
    """Every tool that writes into a case refuses a case in use, naming
    the run; nothing written."""

    def testPlaneWaveInflow(self):
        p = self.holdLock()
        r = subprocess.run(tool("planeWave") + ["-case", self.case,
                                                "-inflow", "2e-6"],
                           capture_output=True, text=True)
        self.assertNotEqual(r.returncode, 0)
        self.assertRegex(r.stderr, r"in use by sleep \(process %d" % p.pid)
        self.assertFalse(os.path.exists(self.case + "/constant"))

    def testSweepCase(self):
        p = self.holdLock()
        self.write("case/system/controlDict", "application sleep;\n"
                   "endTime 1;\n")
        r = subprocess.run(tool("sweepCase") + [
            "-case", self.case, "-entry", "system/controlDict/endTime",
            "-values", "1 2", "-output", "x=log:/(x)/"],
            capture_output=True, text=True)
        self.assertNotEqual(r.returncode, 0)
        self.assertRegex(r.stderr, r"in use by sleep \(process %d" % p.pid)
        self.assertFalse(os.path.exists(self.case + ".sweep_endTime_0"))

    def testCalibrateCell(self):
        p = self.holdLock()
        r = subprocess.run(tool("calibrateCell") + ["-case", self.case,
                                                    "-work", self.tmp + "/w"],
                           capture_output=True, text=True)
        self.assertNotEqual(r.returncode, 0)
        self.assertRegex(r.stderr, r"in use by sleep \(process %d" % p.pid)


    def testPulseStudy(self):
        # adv46b d34: a second study in the folder of a running one took
        # the first's point for interrupted and moved its case copy aside
        p = self.holdLock()
        os.makedirs(self.case + "/postProcessing/pulseStudy/points/p1/case")
        r = subprocess.run(tool("pulseStudy") + ["-case", self.case],
                           capture_output=True, text=True)
        self.assertEqual(r.returncode, 1, r.stderr)
        self.assertRegex(r.stderr, r"pulseStudy: error: the case .*/case is "
                         r"in use by sleep \(process %d.*Nothing was run or "
                         r"moved" % p.pid)
        self.assertEqual(os.listdir(self.case + "/postProcessing/pulseStudy/"
                                    "points/p1"), ["case"])


class PythonLock(TempDirTestCase):

    def testHeldReleasedAndSeenLiveBySolverRule(self):
        case = self.tmp
        code = ("import sys, time\nfrom neuronFsi import caseLock\n"
                "with caseLock.held(sys.argv[1], 'planeWave'):\n"
                "    print('held', flush=True); time.sleep(30)\n")
        p = subprocess.Popen([sys.executable, "-c", code, case],
                             stdout=subprocess.PIPE, text=True, cwd=case)
        self.addCleanup(lambda: (p.kill(), p.wait(), p.stdout.close()))
        self.assertEqual(p.stdout.readline().strip(), "held")
        h = caseLock.read(case + "/.runLock")
        self.assertEqual((h["pid"], h["executable"]), (p.pid, "planeWave"))
        # caseLock.H's rule: the comm name begins the executable
        with open("/proc/%d/comm" % p.pid) as f:
            self.assertEqual(f.read().strip(), "planeWave")
        self.assertFalse(caseLock.stale(h, case))
        with self.assertRaisesRegex(caseLock.CaseLockError,
                                    r"in use by planeWave \(process %d"
                                    % p.pid):
            with caseLock.held(case, "sweepCase"):
                pass
        p.kill()
        p.wait()
        # a killed holder's lock is stale: taken over, then released
        self.assertTrue(caseLock.stale(h, case))
        with caseLock.held(case, "sweepCase"):
            self.assertEqual(caseLock.read(case + "/.runLock")["pid"],
                             os.getpid())
        self.assertFalse(os.path.exists(case + "/.runLock"))

    def testStaleLockTakenByOneOfTwoAtOnce(self):
        # Two tools that find the same stale lock at the same instant:
        # exactly one takes the case (adv46b d67, d77: both removed the
        # stale lock, the second removing the first's new one, and both
        # ran). Eight trials, the two starting at one wall-clock instant,
        # each reading the lock slowly (0.2 s after each read: the window
        # between judging the lock stale and removing it made wide).
        case = self.tmp
        code = ("import sys, time\nfrom neuronFsi import caseLock\n"
                "read = caseLock.read\n"
                "def slowRead(path):\n"
                "    h = read(path); time.sleep(0.2); return h\n"
                "caseLock.read = slowRead\n"
                "t0 = float(sys.argv[2])\n"
                "while time.time() < t0: pass\n"
                "try:\n"
                "    with caseLock.held(sys.argv[1], 'sweepCase'):\n"
                "        print('held', flush=True); time.sleep(1.0)\n"
                "except caseLock.CaseLockError:\n"
                "    print('refused', flush=True)\n")
        for trial in range(8):
            dead = subprocess.Popen(["true"])
            dead.wait()
            with open(case + "/.runLock", "w") as f:
                f.write(caseLock.lockText(dead.pid, "planeWave", case))
            t0 = "%.6f" % (time.time() + 0.5)
            runs = [subprocess.Popen([sys.executable, "-c", code, case, t0],
                                     stdout=subprocess.PIPE,
                                     stderr=subprocess.DEVNULL, text=True,
                                     cwd=case) for _ in range(2)]
            said = sorted(r.communicate(timeout=60)[0].strip() for r in runs)
            self.assertEqual(said, ["held", "refused"],
                             "trial %d: %s" % (trial, said))
            self.assertFalse(os.path.exists(case + "/.runLock"))

    def testSolverRefusesIt(self):
        # a solver's caseLock (C++) sees the lock of a Python tool as live:
        # "in use by planeWave", not taken over as stale
        import shutil
        if not shutil.which("rhoRiemannFoam"):
            self.skipTest("rhoRiemannFoam not built / not on PATH")
        case = self.tmp + "/case"
        os.makedirs(case + "/system")
        code = ("import sys, time\nfrom neuronFsi import caseLock\n"
                "with caseLock.held(sys.argv[2], 'planeWave'):\n"
                "    print('held', flush=True); time.sleep(30)\n")
        p = subprocess.Popen([sys.executable, "-c", code, "-case", case],
                             stdout=subprocess.PIPE, text=True)
        self.addCleanup(lambda: (p.kill(), p.wait(), p.stdout.close()))
        self.assertEqual(p.stdout.readline().strip(), "held")
        r = subprocess.run(["rhoRiemannFoam", "-case", case],
                           capture_output=True, text=True)
        self.assertNotEqual(r.returncode, 0)
        self.assertRegex(r.stdout + r.stderr, r"is in use by planeWave "
                         r"\(process %d" % p.pid)
        self.assertEqual(caseLock.read(case + "/.runLock")["pid"], p.pid)

    def testNotALockNeverTakenOver(self):
        os.mkdir(self.tmp + "/.runLock")
        with self.assertRaisesRegex(caseLock.CaseLockError,
                                    r"\.runLock of the case .* is a "
                                    r"directory, not a lock"):
            with caseLock.held(self.tmp, "planeWave"):
                pass


class LockOnAFullDisk(TempDirTestCase):
    """adv38 x55: planeWave on a full disk said "a file could not be
    written or read: No space left on device", no file named (the lock's
    write fails at its close, naming no file), and left an empty lock"""

    def testNamedAndRemoved(self):
        import errno
        from unittest import mock
        real = os.fdopen

        def full(fd, *a, **k):
            f = real(fd, *a, **k)

            def write(_):
                raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))
            f.write = write
            return f
        with mock.patch.object(caseLock.os, "fdopen", full):
            with self.assertRaisesRegex(
                    caseLock.CaseLockError,
                    "cannot write the run lock %s/.runLock \\(no space left"
                    " on the device of '%s'" % (self.tmp, self.tmp)):
                with caseLock.held(self.tmp, "planeWave"):
                    pass
        self.assertFalse(os.path.exists(os.path.join(self.tmp, ".runLock")))


class RunSeenThroughABindMount(LiveLockTestCase):
    """adv50a k10 (d): a run in the case seen through a bind mount (a
    container's view) wrote its lock with the bind path; the lock was
    judged stale as "running another case" by path text and an Allclean
    removed the results under the running solver. The case is judged by
    its directory's identity."""

    def testLiveRunThroughBindIsNotStale(self):
        if shutil.which("unshare") is None or subprocess.run(
                ["unshare", "-rm", "true"], capture_output=True).returncode:
            self.skipTest("no unshare -rm (user and mount namespaces)")
        bind = os.path.join(self.tmp, "bind")
        os.makedirs(bind)
        # sleep in the case through the bind path, in its own namespace
        p = subprocess.Popen(
            ["unshare", "-rm", "sh", "-c",
             'mount --bind "$0" "$1" && cd "$1" && exec sleep 60',
             self.case, bind])
        self.addCleanup(lambda: (p.kill(), p.wait()))
        for _ in range(100):
            try:
                if os.readlink("/proc/%d/cwd" % p.pid) == bind:
                    break
            except OSError:
                pass
            time.sleep(0.05)
        else:
            self.skipTest("the namespace's sleep did not start")
        with open(self.case + "/.runLock", "w") as f:
            f.write("pid %d\nhost %s\nexecutable sleep\nstarted now\n"
                    "case %s\n" % (p.pid, socket.gethostname(), bind))
        h = caseLock.read(self.case + "/.runLock")
        self.assertFalse(caseLock.stale(h, self.case))
        with self.assertRaisesRegex(caseLock.CaseLockError,
                                    r"in use by sleep \(process %d" % p.pid):
            caseLock.checkFree(self.case, "planeWave")
        # a process in another directory is running another case
        other = os.path.join(self.tmp, "other")
        os.makedirs(other)
        q = subprocess.Popen(["sleep", "60"], cwd=other)
        self.addCleanup(lambda: (q.kill(), q.wait()))
        h["pid"] = q.pid
        self.assertTrue(caseLock.stale(h, self.case))


class UnderItsAllrun(LiveLockTestCase):
    """A tool started by a run that holds the lock (an Allrun: etc/
    RunFunctions allrunLock) runs under it, as the solvers do (caseLock.H
    underAncestor); a live lock of a process that is not its ancestor is
    refused (fix19m + fix19o merged: planeWave inside an Allrun was refused
    by its own Allrun's lock)."""

    def writeLock(self, pid):
        # the holder's own comm name, so that the lock is live by the
        # stale rule and only the ancestor rule lets the tool through
        with open("/proc/%d/comm" % pid) as f:
            comm = f.read().strip()
        with open(self.case + "/.runLock", "w") as f:
            f.write("pid %d\nhost %s\nexecutable %s\nstarted now\n"
                    "case %s\n" % (pid, socket.gethostname(), comm,
                                    os.path.realpath(self.case)))

    def testAncestorsLockIsOwn(self):
        # this process stands for the Allrun: it holds the lock and works
        # in the case (else the stale rule, another case, would let the
        # tool through without the ancestor rule)
        here = os.getcwd()
        os.chdir(self.case)
        self.addCleanup(os.chdir, here)
        self.writeLock(os.getpid())
        caseLock.checkFree(self.case, "planeWave")
        with caseLock.held(self.case, "planeWave") as h:
            self.assertFalse(h.taken)
        self.assertTrue(os.path.exists(self.case + "/.runLock"),
                        "the Allrun's lock must stay")
        # a child tool of this process (the Allrun's planeWave) too
        r = subprocess.run(
            [sys.executable, "-c", "import sys; from neuronFsi import "
             "caseLock; caseLock.checkFree(sys.argv[1], 'planeWave')",
             self.case], capture_output=True, text=True)
        self.assertEqual(r.returncode, 0, r.stderr)

    def testKilledToolInsideALiveAllrun(self):
        """a lock naming a process that is over, taken over from a run
        that goes on (a solver killed inside its Allrun), is that run's,
        not stale (adv36 v69)"""
        p = self.holdLock()
        with open(self.case + "/.runLock") as f:
            allrun = f.read()
        dead = subprocess.Popen(["true"])
        dead.wait()
        with open(self.case + "/.runLock", "w") as f:
            f.write("pid %d\nhost %s\nexecutable planeWave\nstarted now\n"
                    "case %s\n" % (dead.pid, socket.gethostname(),
                                    os.path.realpath(self.case))
                    + "".join("under %s\n" % line
                              for line in allrun.splitlines()))
        with self.assertRaisesRegex(caseLock.CaseLockError,
                                    r"in use by sleep \(process %d" % p.pid):
            caseLock.checkFree(self.case, "planeWave")
        with self.assertRaisesRegex(caseLock.CaseLockError,
                                    r"in use by sleep \(process %d" % p.pid):
            with caseLock.held(self.case, "sweepCase"):
                pass

    def testOthersLockRefused(self):
        p = self.holdLock()
        with self.assertRaisesRegex(caseLock.CaseLockError,
                                    r"in use by sleep \(process %d" % p.pid):
            caseLock.checkFree(self.case, "planeWave")


class LockCutShort(LiveLockTestCase):
    """adv44 a29: a run lock cut after its first line (a power loss or a
    full disk while it was written: "pid 484" alone) was read as a live
    run of the host "" ("in use by another run (process 484 on host ,
    started ;"): a lock lacking its host, executable or start time, or
    whose last line is cut, is damaged - named as such with what to do,
    never taken over nor removed; the same in inUse (planeWave's check)
    and in the Allrun's lock (neuronFsi.allrunLock)."""

    def cuts(self):
        """The texts of a live process's lock cut after each of its first
        four lines, and inside its last line."""
        p = subprocess.Popen(["sleep", "60"], cwd=self.case)
        self.addCleanup(lambda: (p.kill(), p.wait()))
        text = caseLock.lockText(p.pid, "sleep", os.path.realpath(self.case))
        lines = text.split("\n")
        return p, ["\n".join(lines[:n]) + "\n" for n in range(1, 5)] + [
            text[:-3]]

    def testNamedDamagedNeverTakenOver(self):
        from neuronFsi import allrunLock
        p, cuts = self.cuts()
        path = self.case + "/.runLock"
        for text in cuts:
            with open(path, "w") as f:
                f.write(text)
            with self.assertRaisesRegex(
                    caseLock.CaseLockError,
                    r"\.runLock of the case .* is damaged: cut short \(it "
                    r"names process %d but (not its|its last line is cut)"
                    r".*If no run of this case is going on" % p.pid):
                with caseLock.held(self.case, "planeWave"):
                    pass
            self.assertRegex(caseLock.inUse(self.case),
                             r"is damaged: cut short")
            with self.assertRaisesRegex(allrunLock.LockError,
                                        r"is damaged: cut short"):
                allrunLock.take(self.case, os.getpid())
            with open(path) as f:
                self.assertEqual(f.read(), text)

    def testFarLargerThanALockNotRead(self):
        """adv48b g14: a .runLock of 8 GB was read whole (the run sat until
        killed): a file above MAX_LOCK_BYTES is refused as no lock, naming
        its size, without reading it; left as it is"""
        from neuronFsi import allrunLock
        path = self.case + "/.runLock"
        with open(path, "w") as f:
            f.truncate(1 << 20)
        why = (r"is far larger than a lock \(1048576 bytes; a lock is a few "
               r"lines, at most 65536 bytes\): damaged or not a lock")
        with self.assertRaisesRegex(caseLock.CaseLockError, why):
            with caseLock.held(self.case, "planeWave"):
                pass
        self.assertRegex(caseLock.inUse(self.case), why)
        with self.assertRaisesRegex(allrunLock.LockError, why):
            allrunLock.take(self.case, os.getpid())
        self.assertEqual(os.path.getsize(path), 1 << 20)

    def testWholeLockStillLive(self):
        p = self.holdLock()
        self.assertEqual(caseLock.damage(caseLock.read(
            self.case + "/.runLock")), "")
        with self.assertRaisesRegex(caseLock.CaseLockError,
                                    r"is in use by sleep \(process %d"
                                    % p.pid):
            with caseLock.held(self.case, "planeWave"):
                pass


if __name__ == "__main__":
    unittest.main()

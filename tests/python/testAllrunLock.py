"""An Allrun holds its case's run lock, <case>/.runLock (etc/RunFunctions
allrunLock, neuronFsi.allrunLock; issue 19, adv35 c16: two Allruns at once
in one case re-ran each other's meshing): a second Allrun is refused naming
the first's process before it touches anything, the applications an Allrun
starts run under its lock (caseLock.H: a lock of an ancestor), the lock is
removed when the Allrun ends, and a stale one replaced."""
import os
import subprocess
import sys
import time
import unittest

from fixtures import TempDirTestCase
from neuronFsi import allrunLock

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")

# an Allrun as the tutorials write theirs: options checked first
ALLRUN = """#!/bin/bash
cd "${0%/*}" || exit 1
. "$PROJECT_DIR"/etc/RunFunctions
allrunOptions "" "$@" < /dev/null
echo started > started
BODY
"""


def env():
    e = dict(os.environ, PROJECT_DIR=os.path.abspath(ROOT))
    e["PYTHONPATH"] = os.path.join(os.path.abspath(ROOT), "src", "python")
    return e


class AllrunLock(TempDirTestCase):

    def allrun(self, body):
        path = self.write("case/Allrun", ALLRUN.replace("BODY", body))
        os.chmod(path, 0o755)
        return path

    def testSecondAllrunRefusedNamingTheFirst(self):
        script = self.allrun("sleep 3")
        case = os.path.dirname(script)
        first = subprocess.Popen([script], env=env())
        try:
            for _ in range(100):
                if os.path.exists(os.path.join(case, "started")):
                    break
                time.sleep(0.1)
            os.remove(os.path.join(case, "started"))
            second = subprocess.run([script], env=env(),
                                    capture_output=True, text=True)
            self.assertEqual(second.returncode, 1, second.stderr)
            self.assertRegex(
                second.stderr, r"The case %s is in use by Allrun \(process "
                r"%d on host .*lock file %s/\.runLock\)\. Nothing was done"
                % (os.path.realpath(case), first.pid, os.path.realpath(case)))
            # it touched nothing: its body did not run
            self.assertFalse(os.path.exists(os.path.join(case, "started")))
        finally:
            first.wait()
        self.assertEqual(first.returncode, 0)
        self.assertFalse(os.path.exists(os.path.join(case, ".runLock")))

    def testApplicationsRunUnderTheAllrunsLock(self):
        """a solver or utility the Allrun starts runs under its lock
        (caseLock.H), as does a Python tool taking it (allrunLock.take ->
        exit 2), and neither removes it"""
        script = self.allrun(
            "setRiemannProblem > log.app 2>&1\n"
            "/usr/bin/python3 -m neuronFsi.allrunLock take . $BASHPID\n"
            "echo \"take: $?\" > log.take\n"
            "test -f .runLock && echo kept > log.kept")
        case = os.path.dirname(script)
        r = subprocess.run([script], env=env(), capture_output=True,
                           text=True)
        self.assertEqual(r.returncode, 0, r.stderr)
        with open(os.path.join(case, "log.app")) as f:
            log = f.read()
        self.assertIn("Running under the run lock", log)
        self.assertNotIn("is in use by", log)
        with open(os.path.join(case, "log.take")) as f:
            self.assertEqual(f.read().strip(), "take: 2")
        self.assertTrue(os.path.exists(os.path.join(case, "log.kept")))
        self.assertFalse(os.path.exists(os.path.join(case, ".runLock")))

    def testStaleLockReplaced(self):
        script = self.allrun("true")
        case = os.path.dirname(script)
        dead = subprocess.Popen(["true"])
        dead.wait()
        with open(os.path.join(case, ".runLock"), "w") as f:
            f.write("pid %d\nhost %s\nexecutable Allrun\nstarted then\n"
                    "case %s\n" % (dead.pid, os.uname().nodename,
                                   os.path.realpath(case)))
        r = subprocess.run([script], env=env(), capture_output=True,
                           text=True)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIn("Removing the stale run lock", r.stdout)
        self.assertFalse(os.path.exists(os.path.join(case, ".runLock")))

    def testNotALockNeverTakenOver(self):
        os.makedirs(os.path.join(self.tmp, ".runLock"))
        with self.assertRaisesRegex(allrunLock.LockError,
                                    r"is a directory, not a lock"):
            allrunLock.take(self.tmp, os.getpid())


class AllrunKilledAlone(TempDirTestCase):
    """adv36 v69 (v36, v38): the Allrun's shell killed alone while its
    solver runs - SIGTERM (as `kill PID`: its exit trap removed the lock)
    or SIGKILL (the lock named a dead process, stale) - left the solver
    running with no live lock, and a solver started by hand beside it was
    accepted (force.dat got rows of both). A run started under an Allrun's
    lock takes it over (here a tool through caseLock.held, as the solvers
    through caseLock.H), so the lock names the live orphan: a second run
    is refused naming it, and the lock goes with the orphan's end."""

    TOOL = ("import time\n"
            "from neuronFsi import caseLock\n"
            "with caseLock.held('.', 'planeWave'):\n"
            "    open('toolStarted', 'w').close()\n"
            "    time.sleep(4)\n")

    def allrunKilled(self, sig):
        path = self.write("case/Allrun", ALLRUN.replace(
            "BODY", "/usr/bin/python3 -c \"%s\"\n" % self.TOOL))
        os.chmod(path, 0o755)
        case = os.path.dirname(path)
        allrun = subprocess.Popen([path], env=env(), start_new_session=True)
        self.addCleanup(lambda: subprocess.run(
            ["pkill", "-KILL", "-s", str(allrun.pid)]))
        for _ in range(100):
            if os.path.exists(os.path.join(case, "toolStarted")):
                break
            time.sleep(0.1)
        tool = int(subprocess.run(["pgrep", "-s", str(allrun.pid),
                                   "planeWave"], capture_output=True,
                                  text=True).stdout.split()[0])
        os.kill(allrun.pid, sig)
        allrun.wait()
        time.sleep(0.3)
        # the orphan runs on, named by the lock
        self.assertTrue(os.path.exists("/proc/%d" % tool))
        lock = allrunLock.read(os.path.join(case, ".runLock"))
        self.assertEqual(lock["pid"], tool)
        # a run started by hand (a solver: caseLock.H) is refused
        r = subprocess.run(["setRiemannProblem"], cwd=case, env=env(),
                           capture_output=True, text=True)
        self.assertNotEqual(r.returncode, 0)
        self.assertIn("is in use by planeWave (process %d" % tool,
                      r.stdout + r.stderr)
        # ... and so is another Allrun
        r = subprocess.run([path], env=env(), capture_output=True,
                           text=True)
        self.assertEqual(r.returncode, 1, r.stderr)
        self.assertIn("is in use by planeWave (process %d" % tool, r.stderr)
        # the orphan's end: its Allrun is gone, so is the lock
        for _ in range(100):
            if not os.path.exists("/proc/%d" % tool):
                break
            time.sleep(0.1)
        time.sleep(0.2)
        self.assertFalse(os.path.exists(os.path.join(case, ".runLock")))

    def testSigterm(self):
        import signal
        self.allrunKilled(signal.SIGTERM)

    def testSigkill(self):
        import signal
        self.allrunKilled(signal.SIGKILL)

    def testGivenBackToALiveAllrun(self):
        """at the tool's end the lock is the Allrun's again: a second
        Allrun is refused naming the first, which removes it at its end"""
        script = self.write("case/Allrun", ALLRUN.replace(
            "BODY", "/usr/bin/python3 -c \"%s\"\nhead -1 .runLock > "
            "lockAfterTool\necho \"pid $$\" > allrunPid\n"
            % self.TOOL.replace("time.sleep(4)", "time.sleep(0)")))
        os.chmod(script, 0o755)
        case = os.path.dirname(script)
        r = subprocess.run([script], env=env(), capture_output=True,
                           text=True)
        self.assertEqual(r.returncode, 0, r.stderr)
        with open(os.path.join(case, "lockAfterTool")) as f, \
                open(os.path.join(case, "allrunPid")) as g:
            self.assertEqual(f.read(), g.read())
        self.assertFalse(os.path.exists(os.path.join(case, ".runLock")))


class AllcleanLock(TempDirTestCase):
    """adv36 v72: a tutorial's Allclean (here the preview's, copied) removed
    the 0/, mesh and logs of a case whose run went on; it now takes the
    case's run lock like the Allruns: refused while the run goes on, runs
    once it is over (the stale lock replaced), its lock gone at its end."""

    def testRefusedWhileARunGoesOn(self):
        case = os.path.join(self.tmp, "case")
        # a case (Allclean refuses a folder without system/ since fix19g)
        os.makedirs(os.path.join(case, "system"))
        src = os.path.join(ROOT, "tutorials", "blast",
                           "axisymmetricPreview", "Allclean")
        script = os.path.join(case, "Allclean")
        with open(src) as f, open(script, "w") as g:
            g.write(f.read())
        os.chmod(script, 0o755)
        self.write("case/log.cellBlastFoam", "a run's log\n")
        run = subprocess.Popen(["sleep", "30"], cwd=case)
        try:
            with open(os.path.join(case, ".runLock"), "w") as f:
                f.write("pid %d\nhost %s\nexecutable sleep\nstarted now\n"
                        "case %s\n" % (run.pid, os.uname().nodename,
                                        os.path.realpath(case)))
            r = subprocess.run([script], env=env(), capture_output=True,
                               text=True)
            self.assertEqual(r.returncode, 1, r.stdout + r.stderr)
            self.assertIn("is in use by sleep (process %d" % run.pid,
                          r.stderr)
            self.assertTrue(os.path.exists(os.path.join(
                case, "log.cellBlastFoam")), "Allclean removed a log")
        finally:
            run.kill()
            run.wait()
        r = subprocess.run([script], env=env(), capture_output=True,
                           text=True)
        self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
        self.assertFalse(os.path.exists(os.path.join(case,
                                                     "log.cellBlastFoam")))
        self.assertFalse(os.path.exists(os.path.join(case, ".runLock")))


if __name__ == "__main__":
    unittest.main()

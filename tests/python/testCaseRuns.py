"""neuronFsi.caseRuns: a run that an application started and could not
end (the application killed with SIGKILL) is named, and its folder is not
removed or run again under it (issue 19, adv33 x07)."""
import os
import signal
import socket
import subprocess
import sys
import time
import unittest

from fixtures import TempDirTestCase
from neuronFsi import caseRuns

# an application that starts a long run with runIn and is then killed
APP = r"""
import sys
from neuronFsi import caseRuns
caseRuns.runIn(sys.argv[1], "sleep 60; true", "log.run")
"""


def waitFor(path, seconds=20):
    t0 = time.time()
    while not os.path.exists(path):
        if time.time() - t0 > seconds:
            raise AssertionError("%s did not appear" % path)
        time.sleep(0.05)


class CaseRuns(TempDirTestCase):
    def startApplication(self):
        """APP started on a new folder 'point': (folder, its Popen), once
        its marker is written and its shell has started its sleep"""
        folder = os.path.join(self.tmp, "point")
        os.makedirs(folder)
        app = subprocess.Popen([sys.executable, "-c", APP, folder])
        waitFor(os.path.join(folder, caseRuns.MARKER))
        time.sleep(0.3)                 # the shell has started its sleep
        return folder, app

    def testMarkerOnlyWhileRunning(self):
        # the marker is written once the program runs (its group's id is
        # its pid): the command waits for it, up to 10 s
        caseRuns.runIn(self.tmp, "for i in $(seq 100); do test -f %s && "
                       "exit 0; sleep 0.1; done; exit 1" % caseRuns.MARKER,
                       "log")
        self.assertFalse(os.path.exists(
            os.path.join(self.tmp, caseRuns.MARKER)))
        with self.assertRaises(caseRuns.RunError):
            caseRuns.runIn(self.tmp, "exit 3", "log")
        self.assertFalse(os.path.exists(
            os.path.join(self.tmp, caseRuns.MARKER)))

    def testRunLeftByAKilledApplication(self):
        folder, app = self.startApplication()
        app.kill()
        app.wait()
        with open(os.path.join(folder, caseRuns.MARKER)) as f:
            pgid = int(f.read().split()[1])
        try:
            with self.assertRaises(caseRuns.RunError) as c:
                caseRuns.checkNoEarlierRun(folder)
            msg = str(c.exception)
            self.assertIn(folder, msg)
            self.assertIn("process group %d" % pgid, msg)
            self.assertIn("sleep", msg)
            self.assertIn("Nothing was removed", msg)
            # runIn refuses too, before it starts anything
            with self.assertRaises(caseRuns.RunError):
                caseRuns.runIn(folder, "touch started", "log.again")
            self.assertFalse(os.path.exists(os.path.join(folder, "started")))
        finally:
            os.killpg(pgid, signal.SIGKILL)
        t0 = time.time()
        while caseRuns._groupIn(pgid, folder) and time.time() - t0 < 10:
            time.sleep(0.05)
        # the run is over: the marker is stale, removed, runs go on
        caseRuns.checkNoEarlierRun(folder)
        self.assertFalse(os.path.exists(
            os.path.join(folder, caseRuns.MARKER)))
        caseRuns.runIn(folder, "touch started", "log.again")
        self.assertTrue(os.path.exists(os.path.join(folder, "started")))

    def testRunOfALiveApplicationIsNamedAsGoingOn(self):
        # adv37 w63: the run of an application still running was called
        # left by a killed one, with the advice to end its process group
        folder, app = self.startApplication()
        with open(os.path.join(folder, caseRuns.MARKER)) as f:
            pgid = int(f.read().split()[1])
        try:
            with self.assertRaises(caseRuns.RunError) as c:
                caseRuns.checkNoEarlierRun(folder)
            msg = str(c.exception)
            self.assertIn("is going on", msg)
            self.assertIn("(pid %d), is running" % app.pid, msg)
            self.assertNotIn("kill", msg)
            self.assertNotIn("was killed", msg)
            self.assertIsNone(app.poll())       # nothing ended
        finally:
            app.kill()
            app.wait()
            os.killpg(pgid, signal.SIGKILL)

    def testGroupWorkingElsewhereIsNotTheRun(self):
        # a reused group id: live processes, but none in the folder
        self.write(caseRuns.MARKER, "pgid %d\nhost %s\ncommand ./Allrun\n"
                   % (os.getpgrp(), socket.gethostname()))
        self.addCleanup(os.chdir, os.getcwd())
        os.chdir(os.path.dirname(self.tmp))
        caseRuns.checkNoEarlierRun(self.tmp)
        self.assertFalse(os.path.exists(
            os.path.join(self.tmp, caseRuns.MARKER)))

    def testRunOnAnotherHost(self):
        self.write(caseRuns.MARKER, "pgid 12345\nhost elsewhere.example\n"
                   "command ./Allrun -pulse 5e-9\n")
        with self.assertRaises(caseRuns.RunError) as c:
            caseRuns.checkNoEarlierRun(self.tmp)
        self.assertIn("elsewhere.example", str(c.exception))
        self.assertIn(caseRuns.MARKER, str(c.exception))


class RelativeOutside(TempDirTestCase):
    """adv45 b15: the base case's #sinclude "../../shared/override" (a
    Maxwell branch) was not read by pulseStudy's point copies, rc 0: a
    reference to a file outside the case by a path that depends on where
    the case lies is named (caseRuns.relativeOutside), an absolute one or
    one inside the case is not."""

    def testNamed(self):
        self.write("shared/override", "mu2 50;\n")
        self.write("base/system/controlDict", "a 1;\n")
        self.write("base/constant/sub/y", "b 2;\n")
        sp = self.write("base/constant/solidProperties", (
            'materials\n{\n    #sinclude "../../shared/override"\n}\n'
            '#include "sub/y"\n#include "../constant/sub/y"\n'
            '#include "%s/shared/override"\n#sinclude "$HOME/x"\n'
            '#include "$FOAM_CASE/../missing"\n'
            'top { file "$FOAM_CASE/constant/sub/y"; }\n'
            'p { file "<case>/../t.dat"; }\n' % self.tmp))
        base = os.path.dirname(os.path.dirname(sp))
        found = caseRuns.relativeOutside(base)
        self.assertEqual(found, [
            ("constant/solidProperties", '#sinclude "../../shared/override"',
             os.path.join(os.path.realpath(self.tmp), "shared", "override")),
            ("constant/solidProperties", '#include "$FOAM_CASE/../missing"',
             os.path.join(os.path.realpath(self.tmp), "missing")),
            ("constant/solidProperties", 'file "<case>/../t.dat"',
             os.path.join(os.path.realpath(self.tmp), "t.dat"))])
        self.assertRegex(
            caseRuns.relativeOutsideProblem(base, "The study runs copies"),
            r"base reads files outside its folder by a path that depends on "
            r"where the case lies: constant/solidProperties: #sinclude "
            r"\"../../shared/override\" \(here .*/shared/override\);.*The "
            r"study runs copies, where they would read another file or "
            r"none. Nothing was run: give each path absolute")
        self.assertEqual(caseRuns.relativeOutside(base, ("system",)), [])


if __name__ == "__main__":
    unittest.main()

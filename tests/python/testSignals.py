"""neuronFsi.signals: SIGTERM ends the programs a Python application
started and its finally clauses run (adv28 z3: planeWave stopped by
SIGTERM left rhoRiemannFoam running and /tmp/planeWave.* behind)."""
import os
import signal
import subprocess
import sys
import time
import unittest

from fixtures import TempDirTestCase

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))

SCRIPT = r"""
import os, shutil, subprocess, sys
from neuronFsi import signals
work = sys.argv[1]
os.makedirs(os.path.join(work, "scratch"))
with signals.stopOn("t"):
    try:
        p = subprocess.run(["sleep", "60"])
    finally:
        shutil.rmtree(os.path.join(work, "scratch"))
print("not reached")
"""


def alive(pid):
    try:
        with open("/proc/%d/stat" % pid) as f:
            return f.read().split(")")[-1].split()[0] != "Z"
    except OSError:
        return False


class StopOn(TempDirTestCase):

    def stop(self, signum):
        p = subprocess.Popen(
            [sys.executable, "-c", SCRIPT, self.tmp], stdout=subprocess.PIPE,
            stderr=subprocess.PIPE, text=True,
            env=dict(os.environ, PYTHONPATH=os.path.join(ROOT, "src/python")))
        child = None
        for _ in range(100):            # the child sleep started
            time.sleep(0.1)
            kids = subprocess.run(["pgrep", "-P", str(p.pid)],
                                  capture_output=True, text=True).stdout
            if kids.strip():
                child = int(kids.split()[0])
                break
        self.assertIsNotNone(child, "the script did not start its child")
        p.send_signal(signum)
        out, err = p.communicate(timeout=30)
        return p.returncode, out, err, child

    def testTermEndsChildAndCleansUp(self):
        for signum in (signal.SIGTERM, signal.SIGHUP):
            code, out, err, child = self.stop(signum)
            self.assertEqual(code, 128 + signum, err)
            self.assertNotIn("Traceback", err)
            self.assertIn("t: stopped by %s" % signal.Signals(signum).name,
                          err)
            self.assertEqual(out, "")
            self.assertFalse(alive(child), "the child runs on")
            self.assertFalse(os.path.exists(os.path.join(self.tmp,
                                                         "scratch")))

    def testHandlersRestored(self):
        from neuronFsi import signals
        before = signal.getsignal(signal.SIGTERM)
        with signals.stopOn("t"):
            self.assertNotEqual(signal.getsignal(signal.SIGTERM), before)
        self.assertEqual(signal.getsignal(signal.SIGTERM), before)


if __name__ == "__main__":
    unittest.main()

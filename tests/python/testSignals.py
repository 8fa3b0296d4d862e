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
import concurrent.futures, os, shutil, sys
from neuronFsi import signals
work = sys.argv[1]
os.makedirs(os.path.join(work, "scratch"))
def run(i):
    rc = signals.call("sleep %s; true" % sys.argv[2], shell=True)
    # the thread tells the stop from a failure of its run
    sys.stderr.write("run ended: exit %d, stopped by %s\n"
                     % (rc, signals.stopped()))
with signals.stopOn("t"):
    try:
        # three runs on two threads (one waits), each a shell command
        # whose sleep is the shell's child (not exec'd)
        with concurrent.futures.ThreadPoolExecutor(2) as pool:
            list(pool.map(run, range(3)))
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

    def stop(self, signum, tag):
        """Run SCRIPT, send signum once its two shells run their sleep
        (of tag seconds: found by pgrep); (exit code, stdout, stderr,
        sleeps left)."""
        p = subprocess.Popen(
            [sys.executable, "-c", SCRIPT, self.tmp, tag],
            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
            env=dict(os.environ, PYTHONPATH=os.path.join(ROOT, "src/python")))
        sleeps = []
        for _ in range(100):
            time.sleep(0.1)
            sleeps = self.sleeps(tag)
            if len(sleeps) == 2:
                break
        self.assertEqual(len(sleeps), 2, "the two runs did not start")
        p.send_signal(signum)
        out, err = p.communicate(timeout=30)
        time.sleep(0.2)
        return p.returncode, out, err, [q for q in sleeps if alive(q)] \
            + [q for q in self.sleeps(tag) if q not in sleeps]

    @staticmethod
    def sleeps(tag):
        r = subprocess.run(["pgrep", "-f", "^sleep %s$" % tag],
                           capture_output=True, text=True)
        return [int(x) for x in r.stdout.split()]

    def testSignalEndsEveryRunAndCleansUp(self):
        for i, signum in enumerate((signal.SIGTERM, signal.SIGHUP,
                                    signal.SIGINT)):
            tag = "61.%d%d" % (os.getpid() % 1000, i)
            code, out, err, left = self.stop(signum, tag)
            self.assertEqual(code, 128 + signum, err)
            self.assertNotIn("Traceback", err)
            self.assertIn("t: stopped by %s" % signal.Signals(signum).name,
                          err)
            self.assertIn("run ended: exit -9, stopped by %d" % signum, err)
            self.assertEqual(out, "")
            self.assertEqual(left, [], "runs left running")
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

"""A termination signal (SIGTERM: timeout, a batch system, kill; SIGHUP: a
closed terminal; SIGINT: Ctrl-C) as an exception, with every program
started through call() ended first, so that a Python application that
runs other programs (in threads too) leaves none running and its finally
clauses remove its scratch folders (issue 19, adversarial pass adv28 z3:
planeWave stopped by SIGTERM left its rhoRiemannFoam running as an orphan
and /tmp/planeWave.* behind).

    with signals.stopOn("planeWave"):
        try:
            rc = signals.call(["rhoRiemannFoam", ...], stdout=log)
        finally:
            ...  # remove the scratch folder

call() starts the program in a process group of its own (a shell command
with the programs it starts); on the signal the handler kills every
group still running (SIGKILL: their results are discarded), later call()s
start nothing, and the application exits with 128 + the signal's number
(143 for SIGTERM), as a shell reports a process the signal ended. SIGKILL
of the application itself cannot be caught."""

import contextlib
import os
import signal
import subprocess
import sys
import threading

SIGNALS = (signal.SIGTERM, signal.SIGHUP, signal.SIGINT)

_children = set()
_lock = threading.Lock()
_stopped = []                   # the signal's number, once it came


class Stopped(SystemExit):
    """Raised by the handler: a SystemExit with the shell's exit code."""

    def __init__(self, signum):
        super().__init__(128 + signum)
        self.signum = signum


def stopped():
    """The number of the signal that came, or None: a thread whose run
    call() ended can tell a stop from a failure."""
    return _stopped[0] if _stopped else None


def _kill(p):
    try:
        os.killpg(p.pid, signal.SIGKILL)
    except OSError:             # gone already
        pass


def call(cmd, started=None, **kwargs):
    """subprocess.call(cmd, **kwargs) in a process group of its own, which
    stopOn's handler kills; Stopped instead of a start once a signal
    came. started(p), if given, is called with the Popen once the program
    runs (its pid is its process group's id)."""
    with _lock:
        if _stopped:
            raise Stopped(_stopped[0])
        p = subprocess.Popen(cmd, start_new_session=True, **kwargs)
        _children.add(p)
    try:
        if started:
            started(p)
        if _stopped:            # the handler ran while p was starting
            _kill(p)
        return p.wait()
    finally:
        if p.returncode is None:
            _kill(p)
            p.wait()
        with _lock:
            _children.discard(p)


@contextlib.contextmanager
def stopOn(prog, signals=SIGNALS):
    """Inside the block, each of signals kills the programs call() started
    and raises Stopped (after a line on stderr naming prog and the
    signal); the former handlers afterwards. Outside the main thread
    (where handlers cannot be set) nothing changes."""
    def handler(signum, frame):
        # once: a second signal while cleaning up does not interrupt it
        for s in signals:
            signal.signal(s, signal.SIG_IGN)
        _stopped.append(signum)         # no lock: the main thread may hold
        for p in list(_children):       # it in call()
            _kill(p)
        print("%s: stopped by %s: the programs it started are ended"
              % (prog, signal.Signals(signum).name), file=sys.stderr)
        raise Stopped(signum)
    former = {}
    try:
        for s in signals:
            former[s] = signal.signal(s, handler)
    except ValueError:          # not the main thread
        for s, h in former.items():
            signal.signal(s, h)
        former = {}
    try:
        yield
    finally:
        for s, h in former.items():
            signal.signal(s, h)

"""A termination signal (SIGTERM: timeout, a batch system, kill; SIGHUP: a
closed terminal) as an exception, so that a Python application that runs
another program ends it and removes its scratch folders on the way out
(issue 19, adversarial pass adv28 z3: planeWave stopped by SIGTERM left
its rhoRiemannFoam running as an orphan and /tmp/planeWave.* behind).

    with signals.stopOn("planeWave"):
        ...  # subprocess.run(...) in try/finally

subprocess.run kills its child on any exception, and finally clauses run;
the application then exits with 128 + the signal's number (143 for
SIGTERM), as a shell reports a process the signal ended. SIGINT (Ctrl-C)
is Python's KeyboardInterrupt already. SIGKILL cannot be caught."""

import contextlib
import signal
import sys

SIGNALS = (signal.SIGTERM, signal.SIGHUP)


class Stopped(SystemExit):
    """Raised by the handler: a SystemExit with the shell's exit code."""

    def __init__(self, signum):
        super().__init__(128 + signum)
        self.signum = signum


@contextlib.contextmanager
def stopOn(prog, signals=SIGNALS):
    """Inside the block, each of signals raises Stopped (after a line on
    stderr naming prog and the signal); the former handlers afterwards.
    Outside the main thread (where handlers cannot be set) nothing
    changes."""
    def handler(signum, frame):
        # once: a second signal while cleaning up does not interrupt it
        for s in signals:
            signal.signal(s, signal.SIG_IGN)
        print("%s: stopped by %s: the programs it started are ended and "
              "its scratch folders removed" % (prog,
                                               signal.Signals(signum).name),
              file=sys.stderr)
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

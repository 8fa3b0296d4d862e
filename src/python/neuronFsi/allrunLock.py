"""An Allrun holds its case's run lock, the one our solvers take
(src/foamTools/caseLock.H, <case>/.runLock), from its start to its end:
one run per case (issue 19, adv35 c16: a second Allrun started in a case
whose Allrun was running re-ran blockMesh and restore0Dir on it, then
failed with "tail: cannot open ...coupling.dat").

    python3 -m neuronFsi.allrunLock take CASE PID     (etc/RunFunctions)
    python3 -m neuronFsi.allrunLock release CASE PID

take writes the lock for the process PID (the Allrun's shell, $$) in
caseLock.H's format (pid, host, executable: the process's comm name,
started, case: the real path), created with O_CREAT | O_EXCL. A lock of
a live run of this host is refused naming it, exit 1, before the Allrun
touches anything; a stale lock (caseLock.H's rule: its process is gone,
runs another executable or works on another case) is replaced with a line
saying so; what is not a lock (a directory, a FIFO, an empty or damaged
file) and a lock of another host are never taken over. The solvers,
utilities and tools the Allrun starts take its lock over until their end
(a lock held by an ancestor of the process is its own run's; caseLock.H:
underAncestor, takeOver), as does an Allrun started by an Allrun of the
same case (exit 0, its exit trap gives the lock back). release gives the
lock back if it is PID's, or names a process of PID's run that is over
(caseLock.H's giveBack: the lock taken over if that run still goes on,
else none): the Allrun's exit trap. An Allrun's shell killed while its
solver runs leaves the lock naming the solver (adv36 v69: its exit trap
removed the lock and a second solver ran beside the orphaned one)."""

import os
import socket
import sys
import time

# one lock, one implementation: the file, its reader and the stale and
# ancestor rules are neuronFsi.caseLock's (the Python tools' side of
# caseLock.H)
from .caseLock import FILE, _notAFile, _running as comm, damage, \
    directoryMutex, giveBack, holding, isAncestor, lockText, read, stale, takeOver


class LockError(Exception):
    pass


def take(case, pid):
    """Write case's lock for process pid; LockError naming the run that
    holds it. A lock of pid or of an ancestor of pid is kept (an Allrun
    started by another Allrun of the same case)."""
    real = os.path.realpath(case)
    with directoryMutex(real):
        return _takeLocked(real, pid)


def _takeLocked(real, pid):
    """take's read, judge, remove and create, under the case directory's
    mutex."""
    path = os.path.join(real, FILE)
    for attempt in range(2):
        try:
            fd = os.open(path, os.O_CREAT | os.O_EXCL | os.O_WRONLY, 0o644)
        except FileExistsError:
            pass
        except OSError as err:
            raise LockError("Cannot create the run lock %s: %s. The case "
                            "directory must be writable." % (path,
                                                             err.strerror))
        else:
            with os.fdopen(fd, "w") as f:
                f.write(lockText(pid, comm(pid) or "Allrun", real))
            return True
        h = read(path)
        if h["readable"] and damage(h):
            time.sleep(0.5)         # a run starting: not written yet
            h = read(path)
        what = _notAFile(path) or damage(h)
        if what:
            raise LockError(
                "The run lock %s of the case %s is %s, not a lock this run "
                "can check. If no run of this case is going on (or "
                "starting), remove it; otherwise wait for that run to end."
                % (path, real, what))
        h = holding(h)
        if h["host"] == socket.gethostname() and isAncestor(h["pid"], pid) \
                and comm(h["pid"]):
            if h["pid"] == pid:
                return False        # this run's own lock
            # an Allrun of the same case started by this run: it takes the
            # lock over until its end (its exit trap gives it back)
            if takeOver(path, pid, comm(pid) or "Allrun", real, h["pid"]):
                return True
            continue
        if attempt > 0 or not stale(h, real):
            raise LockError(
                "The case %s is in use by %s (process %d on host %s, started "
                "%s; lock file %s). Nothing was done. One run per case: wait "
                "for that run to end or stop it, or copy the case. If that "
                "run is over (a run on another host cannot be checked from "
                "here), remove %s."
                % (real, h["executable"] or "another run", h["pid"],
                   h["host"], h["started"], path, path))
        print("Removing the stale run lock %s of %s (process %d on %s, "
              "started %s; no longer running, or running another case)"
              % (path, h["executable"], h["pid"], h["host"], h["started"]))
        try:
            os.unlink(path)
        except FileNotFoundError:
            pass
    raise LockError("Cannot take the run lock %s: it changed twice while "
                    "this run looked at it (other runs starting or "
                    "ending). Start again." % path)


def release(case, pid):
    """Give case's lock back at the end of pid's run (caseLock.giveBack)."""
    giveBack(os.path.join(os.path.realpath(case), FILE), pid)


def busyUnder(paths):
    """[(folder, why)] of the runs going on (caseLock.inUse: a live lock,
    a run caseRuns started) in the folders under paths (each path itself
    and every folder below it, links not followed) that hold a run lock
    or a run marker: what an Allclean removing paths would remove under a
    running run (adv51 n09: the paper's Allclean removed a running
    cellBlastFoam's case under postProcessing/runs/; n10: the calibration
    Allclean removed validationCell/ under predictValidation.py's
    cellIndentationFoam)."""
    from . import caseRuns
    from .caseLock import FILE, inUse
    busy = []
    for path in paths:
        if os.path.islink(path) or not os.path.isdir(path):
            continue
        for d, dirs, files in os.walk(path):
            dirs[:] = [x for x in dirs
                       if not os.path.islink(os.path.join(d, x))]
            if FILE in files or caseRuns.MARKER in files:
                why = inUse(d)
                if why:
                    busy.append((d, why))
    return busy


def main(argv):
    if len(argv) >= 2 and argv[0] == "free":
        # free PROG PATH...: exit 1 naming each run going on under PATHs
        busy = busyUnder(argv[2:])
        for d, why in busy:
            print("%s: error: %s: %s; it would be removed under that run."
                  " Wait for it to end or stop it. Nothing was removed."
                  % (argv[1], os.path.abspath(d), why), file=sys.stderr)
        return 1 if busy else 0
    if len(argv) != 3 or argv[0] not in ("take", "release") \
            or not argv[2].isdigit():
        sys.exit("usage: python3 -m neuronFsi.allrunLock take|release CASE "
                 "PID")
    case, pid = argv[1], int(argv[2])
    if argv[0] == "release":
        release(case, pid)
        return 0
    try:
        # exit 2: held by pid already (not this call's to give back)
        return 0 if take(case, pid) else 2
    except LockError as err:
        print("%s: %s" % (comm(pid) or "Allrun", err), file=sys.stderr)
        return 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))

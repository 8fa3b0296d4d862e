"""Runs of a case's copies, several at a time: what sweepCase and
pulseStudy (applications/utilities) share.

    wall = runIn(copy, "./Allrun -pulse 5e-9", "log.pulseStudy")
    results = inParallel(nProcs, job, items)

runIn runs a shell command in a folder with its output in a log there
(signals.call: a termination signal ends it and what it started), and
raises RunError naming the command, its exit code and the log when it
fails. inParallel calls job(item) for every item, nProcs at a time (threads;
each job runs its own program), and returns the results in the items'
order; the first exception of a job is raised once the others are done.
"""

import concurrent.futures
import os
import subprocess
import time

from . import signals


class RunError(Exception):
    pass


def runIn(folder, command, log):
    """Run the shell command in folder, its stdout and stderr to
    folder/log (log itself if absolute); the wall time [s]. RunError if it
    fails."""
    t0 = time.time()
    path = os.path.join(folder, log)
    with open(path, "w") as f:
        # ended, with what the shell started, on SIGTERM, SIGHUP, SIGINT
        rc = signals.call(command, shell=True, cwd=folder, stdout=f,
                          stderr=subprocess.STDOUT)
    if rc:
        raise RunError("'%s' failed (exit %d), see %s" % (command, rc, path))
    return time.time() - t0


def inParallel(nProcs, job, items):
    """[job(item) for item in items], nProcs at a time."""
    with concurrent.futures.ThreadPoolExecutor(nProcs) as pool:
        return list(pool.map(job, items))

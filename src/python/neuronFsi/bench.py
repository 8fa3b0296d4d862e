"""What the benchmark scripts (bench/) share: their options, the project's
environment, commands run with their log, a solver run timed by
/usr/bin/time -v, the commit a run measures (stamped in its level folders
for a later --reportOnly), the coupling statistics of a blast run and the
report file.

A level folder is one benchmark run: runTimed leaves in it log.time
(/usr/bin/time -v, read by logs.timeV), the solver log and log.load (the
load average at its end); stampCommit leaves bench.commit.
"""

import argparse
import datetime
import math
import os
import subprocess
import sys

import numpy as np

from . import options, postProcessing

COMMIT_FILE = "bench.commit"
LOAD_FILE = "log.load"


def arguments(doc, out, quick=None):
    """The options every benchmark has: --quick (help: quick), --out (the
    folder of the runs, default out) and --doc (the report file); the
    description is the first line of doc."""
    ap = argparse.ArgumentParser(description=doc.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help=quick)
    ap.add_argument("--out", default=out)
    ap.add_argument("--doc", default=None)
    return ap


class BenchError(RuntimeError):
    """A benchmark that cannot run or report: a command that failed, runs
    that are missing (--reportOnly); the message says which."""


# the options whose value is a list of words (each a positive number, or a
# positive whole number)
_LISTS = {"factors": float, "sizes": int, "subcycles": int}


def parse(ap, argv=None):
    """The options of a benchmark's parser ap, checked before anything
    runs (issue 19, bk06, bk07: a bad option was a Python traceback
    after minutes, or went unnoticed): options.parse (a negative number
    as a value, an option given twice, numbers outside OpenFOAM's reader),
    then each number finite, positive (at least 0 where the default is 0),
    each word of --factors (a positive number), --sizes and --subcycles (a
    positive whole number), --out not a file, --doc not a folder. A usage
    error naming the option and what is valid (exit 2)."""
    a = options.parse(ap, argv)
    for act in ap._actions:
        if not act.option_strings or act.dest not in vars(a):
            continue
        name, v = act.option_strings[-1], getattr(a, act.dest)
        if act.type in (int, float) and v is not None:
            low = 0 if act.default == 0 else None
            if not (math.isfinite(v) and (v >= 0 if low == 0 else v > 0)):
                ap.error("%s %s: not a finite number in the valid range %s"
                         % (name, v, "[0, inf)" if low == 0 else "(0, inf)"))
        if act.dest in _LISTS and isinstance(v, str):
            kind = _LISTS[act.dest]
            for w in v.split():
                try:
                    x = kind(w)
                except ValueError:
                    x = None
                if x is None or not (math.isfinite(x) and x > 0):
                    ap.error("%s '%s': '%s' is not a positive %s"
                             % (name, v, w, "number" if kind is float
                                else "whole number"))
            if not v.split():
                ap.error("%s '%s': no value" % (name, v))
    for dest, isDir in (("out", True), ("doc", False)):
        v = getattr(a, dest, None)
        if v is None:
            continue
        full = os.path.abspath(v)
        if not isDir and os.path.isdir(full):
            ap.error("--doc %s: a folder; the option names a report file"
                     % v)
        # the first existing path up from the folder must be a folder
        p = full if isDir else os.path.dirname(full)
        while not os.path.lexists(p) and p != os.path.dirname(p):
            p = os.path.dirname(p)
        if os.path.lexists(p) and not os.path.isdir(p):
            ap.error("--%s %s: %s is %s, not a folder" % (
                dest, v, p, options.notARegularFile(p) or "a file"))
    return a


def main(fn):
    """Run a benchmark's main function fn; the project's errors (a failed
    command, a missing or unreadable run or log: BenchError and the
    readers' errors) end it with "<script>: error: <message>", exit 1,
    instead of a traceback."""
    from . import foamDict, logs, planeWave, postProcessing, scratch
    errors = (BenchError, logs.LogError, postProcessing.ColumnFileError,
              planeWave.PlaneWaveError, foamDict.DictError,
              scratch.ScratchError)
    try:
        return fn()
    except errors as err:
        sys.exit("%s: error: %s" % (os.path.basename(sys.argv[0]), err))


def reportPath(doc, quick, out, root, name):
    """The report file: doc (--doc) if given, else out/name with --quick,
    else root/docs/benchmarks/name."""
    return doc or (os.path.join(out, name) if quick
                   else os.path.join(root, "docs", "benchmarks", name))


def foamEnv(root):
    """The environment of root/etc/bashrc, sourced once."""
    res = subprocess.run(["bash", "-c", f". '{root}/etc/bashrc' > /dev/null"
                          " 2>&1 && env -0"], stdout=subprocess.PIPE,
                         check=True)
    return dict(v.split("=", 1) for v in
                res.stdout.decode().split("\0") if "=" in v)


def runLogged(command, cwd, env, log=None):
    """Run command (a list) in cwd, standard error with standard output,
    which goes to cwd/log if given; the CompletedProcess."""
    res = subprocess.run(command, cwd=cwd, env=env, stdout=subprocess.PIPE,
                         stderr=subprocess.STDOUT, text=True)
    if log:
        with open(os.path.join(cwd, log), "w") as f:
            f.write(res.stdout)
    return res


def fail(res, message):
    """Show the end of a failed command's output and raise message."""
    sys.stdout.write(res.stdout[-3000:])
    raise BenchError(message)


def runTimed(case, command, env, log):
    """Run command (a list) in case under /usr/bin/time -v (its report in
    log.time), its output in case/log; then the load average in
    log.load. A failure shows in log.time (logs.timeV's status)."""
    with open(os.path.join(case, log), "w") as out:
        subprocess.run(["/usr/bin/time", "-v", "-o", "log.time"] + command,
                       cwd=case, env=env, stdout=out,
                       stderr=subprocess.STDOUT)
    with open(os.path.join(case, LOAD_FILE), "w") as o:
        o.write("%.2f %.2f %.2f\n" % os.getloadavg())


def loadAverage(case):
    """The load average (1, 5, 15 min) that runTimed stored; three nan
    without it."""
    p = os.path.join(case, LOAD_FILE)
    if not os.path.exists(p):
        return [float("nan")]*3
    with open(p) as f:
        return [float(v) for v in f.read().split()]


def loadColumn(load):
    """A table cell of the 1 min load average, "-" when unknown."""
    return "-" if math.isnan(load[0]) else f"{load[0]:.2f}"


def commit(root):
    """The short hash of HEAD of the checkout root."""
    return subprocess.run(["git", "rev-parse", "--short", "HEAD"], cwd=root,
                          stdout=subprocess.PIPE, text=True).stdout.strip()


def measuredCode(scene):
    """The folders whose code a benchmark of the scene (a tutorials/ and
    bench/ folder) measures, and their description."""
    return (["src", "applications", f"tutorials/{scene}", f"bench/{scene}"],
            f"src/, applications/, tutorials/{scene} or bench/{scene}")


def uncommitted(root, paths):
    """git status --porcelain of paths in root: empty when they are clean."""
    return subprocess.run(["git", "status", "--porcelain", "--"] + paths,
                          cwd=root, stdout=subprocess.PIPE,
                          text=True).stdout.strip()


def stampCommit(folder, commitId, dirty):
    """Record in folder the commit a level ran with ("+": uncommitted
    changes), for a later report from the level folders."""
    with open(os.path.join(folder, COMMIT_FILE), "w") as o:
        o.write(commitId + ("+" if dirty else "") + "\n")


def stampedCommit(folders, given=None):
    """(commit, dirty) of level folders stamped by stampCommit (dirty: ""
    or "yes"); given overrides the stamps. A RuntimeError when they do not
    name one commit."""
    info = set()
    for c in folders:
        p = os.path.join(c, COMMIT_FILE)
        if os.path.exists(p):
            with open(p) as f:
                info.add(f.read().strip())
    if given:
        info = {given}
    if len(info) != 1:
        raise RuntimeError("--reportOnly: the levels' commit is unknown "
                           f"or not one ({info}); give --commit")
    commitId = info.pop()
    if commitId.endswith("+"):
        return commitId[:-1], "yes"
    return commitId, ""


def runPeriod(firsts, lasts):
    """(start, end) UTC of runs already made: the oldest modification of
    the files firsts (written when a run starts) and the newest of lasts
    (written when it ends)."""
    return (datetime.datetime.utcfromtimestamp(min(map(os.path.getmtime,
                                                       firsts))),
            datetime.datetime.utcfromtimestamp(max(map(os.path.getmtime,
                                                       lasts))))


def writtenBy(script, start, commitId, mode=None, dirty="", changes=""):
    """The report's first words: script (mode) on start UTC, commit
    commitId, and with dirty, " (with uncommitted changes[ in changes])"."""
    return (f"Written by `{script}`" + (f" ({mode})" if mode else "")
            + f" on {start.strftime('%Y-%m-%d %H:%M')} UTC, commit "
            + commitId
            + ((" (with uncommitted changes"
                + (f" in {changes}" if changes else "") + ")")
               if dirty else ""))


def levelsWrittenBy(script, mode, start, end, commitId, dirty, changes,
                    reportOnly):
    """writtenBy of a ladder of levels run one after the other from start
    to end [UTC], and when the text is regenerated from them
    (reportOnly), when that was."""
    return (writtenBy(script, start, commitId, mode, dirty, changes)
            + f", {(end - start).total_seconds():.0f} s in all, the levels"
            " one after the other"
            + (" (this text regenerated with --reportOnly on "
               f"{datetime.datetime.utcnow().strftime('%Y-%m-%d %H:%M')} "
               "UTC from the same level cases)" if reportOnly else ""))


def couplingStatistics(case):
    """Of a coupled run's postProcessing/fsi/coupling.dat (stitched over
    restarts): time steps, mean and largest coupling passes per step,
    unconverged steps, least, largest and median time step [s]."""
    d = postProcessing.series(case, "fsi/coupling.dat")
    return dict(steps=len(d), itMean=d[:, 2].mean(),
                itMax=int(d[:, 2].max()),
                notConverged=int(np.sum(d[:, 4] == 0)), dtMin=d[:, 1].min(),
                dtMax=d[:, 1].max(), dtMedian=float(np.median(d[:, 1])))


def writeReport(path, lines):
    """Write the report's lines to path (its folder made), print them and
    where they went."""
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    with open(path, "w") as f:
        f.write("\n".join(lines))
    print("\n".join(lines))
    print(f"wrote {path}")

"""Runs of a case's copies, several at a time: what sweepCase and
pulseStudy (applications/utilities) share.

    wall = runIn(copy, "./Allrun -pulse 5e-9", "log.pulseStudy")
    results = inParallel(nProcs, job, items)

runIn runs a shell command in a folder with its output in a log there
(signals.call: a termination signal ends it and what it started), and
raises RunError naming the command, its exit code and the log when it
fails. While the command runs, folder/.caseRun names its process group
(pgid, host, command, and the pid and start time of the application that
started it): an application killed with SIGKILL cannot end the
runs it started, and these go on in their folders; checkNoEarlierRun(
folder) raises RunError naming such a run (processes of that group whose
working directory is in the folder) before the folder is removed or run
again (issue 19, adv33 x07: pulseStudy started again replaced a point's
folder under the run its SIGKILLed predecessor had left); a run whose
starter still runs is named as going on (adv37 w63: a second pulseStudy
beside a running one was told to kill the live run's group). inParallel calls job(item) for every item, nProcs at a time (threads;
each job runs its own program), and returns the results in the items'
order; the first exception of a job is raised once the others are done.
"""

import concurrent.futures
import os
import re
import socket
import subprocess
import time

from . import signals


class RunError(Exception):
    pass


MARKER = ".caseRun"


def _marker(folder):
    """(pgid, host, command) of folder's marker, or None."""
    try:
        with open(os.path.join(folder, MARKER)) as f:
            w = f.read().split("\n")
        return int(w[0].split()[1]), w[1].split(None, 1)[1], \
            w[2].split(None, 1)[1]
    except (OSError, ValueError, IndexError):
        return None


def _starter(folder):
    """(pid, start time) of the application that started the run of
    folder's marker (its line "starter <pid> <start time>"), None if the
    marker has none (written before it was recorded) or there is none."""
    try:
        with open(os.path.join(folder, MARKER)) as f:
            for line in f:
                if line.startswith("starter "):
                    w = line.split()
                    return int(w[1]), w[2]
    except (OSError, ValueError, IndexError):
        pass
    return None


def _startTime(pid):
    """The start time of process pid (/proc/<pid>/stat, field 22, in clock
    ticks since boot: with the pid, it tells a process from a later one
    given the same pid), None if there is none."""
    try:
        with open("/proc/%s/stat" % pid) as f:
            stat = f.read()
        return stat[stat.rindex(")") + 2:].split()[19]
    except (OSError, ValueError, IndexError):
        return None


def procStat(pid):
    """(name, state, parent pid, process group) of process pid from
    /proc/<pid>/stat (this host), None if there is none; the one reader of
    that file for caseRuns and caseLock."""
    try:
        with open("/proc/%s/stat" % pid) as f:
            stat = f.read()
        name = stat[stat.index("(") + 1:stat.rindex(")")]
        rest = stat[stat.rindex(")") + 2:].split()
        return name, rest[0], int(rest[1]), int(rest[2])
    except (OSError, ValueError, IndexError):
        return None


def _groupIn(pgid, folder):
    """[(pid, name)] of the live processes of group pgid whose working
    directory is folder or below it (/proc of this host)."""
    real = os.path.realpath(folder)
    found = []
    for d in os.listdir("/proc"):
        if not d.isdigit():
            continue
        st = procStat(d)
        if st is None or st[1] == "Z" or st[3] != pgid:
            continue
        name = st[0]
        try:
            cwd = os.readlink("/proc/%s/cwd" % d)
        except OSError:
            continue
        if cwd == real or cwd.startswith(real + os.sep):
            found.append((int(d), name))
    return found


def checkNoEarlierRun(folder):
    """RunError if a run that runIn started in folder (its marker) still
    has processes working there: started by an application that was killed
    without ending it. A marker without such processes is removed."""
    m = _marker(folder)
    if m is None:
        return
    pgid, host, command = m
    starter = _starter(folder)
    if host != socket.gethostname():
        raise RunError(
            "%s: a run ('%s') was started there on host %s and may still "
            "go on; it cannot be checked from here. Nothing was removed: "
            "if it is over, remove %s" % (folder, command, host,
                                          os.path.join(folder, MARKER)))
    procs = _groupIn(pgid, folder)
    if procs and starter is not None and _startTime(starter[0]) == starter[1]:
        # the application that started it runs too: a live run, not one
        # left by a killed application (adv37 w63: a second pulseStudy
        # beside a running one was told to kill the first one's run)
        st = procStat(starter[0])
        raise RunError(
            "%s: a run started there ('%s', process group %d) is going on: "
            "the application that started it, %s (pid %d), is running. "
            "Nothing was removed or started: wait for it to end (ending "
            "that run would stop the other application's work)"
            % (folder, command, pgid, st[0] if st else "?", starter[0]))
    if procs:
        raise RunError(
            "%s: a run started there earlier ('%s') still goes on: process "
            "group %d (%s), left by an application that was killed (SIGKILL "
            "cannot end the runs it started). Nothing was removed: wait for "
            "it to end or end it with 'kill -- -%d', then start again"
            % (folder, command, pgid, ", ".join(
                "%s pid %d" % (n, p) for p, n in procs[:4]), pgid))
    try:
        os.remove(os.path.join(folder, MARKER))
    except OSError:
        pass


def filesNotTheRuns(folder, inputs, outputs=(), end=None):
    """The files under a run's folder (relative paths, sorted) that the run
    did not write, as far as can be told, before an application removes
    the folder it made (sweepCase's run folders, paperFigures' runs;
    issue 19, adv44 a14, a12: the user's notes saved there were removed
    with it): not one of inputs (the files copied in before the run) or
    outputs (files the run is known to write), and written after the run
    ended (end: s since the epoch, if known), or a plain file at the top
    of the folder other than a log (log.*) and the run's records (the
    case lock, this module's marker, the Allrun options' record). A file
    saved during the run into a folder the run writes (postProcessing/...)
    is not told apart from the run's."""
    from . import caseLock
    records = {MARKER, caseLock.FILE, ".allrunOptions"}
    found = []
    for d, dirs, names in os.walk(folder):
        rel = os.path.relpath(d, folder)
        links = [n for n in dirs if os.path.islink(os.path.join(d, n))]
        for n in names + links:
            r = os.path.normpath(os.path.join(rel, n))
            if r in inputs or r in outputs:
                continue
            try:
                late = end is not None and \
                    os.lstat(os.path.join(d, n)).st_mtime > end
            except OSError:
                continue
            top = rel == "." and not n.startswith("log.") and \
                n not in records
            if late or top:
                found.append(r)
    return sorted(found)


def asideName(path, what="interrupted"):
    """The free name path.<what>, path.<what>1, ... that a run's folder
    (or case copy) is moved to, whole, instead of being removed: an
    interrupted run's copy may hold a file of the user's among the run's
    (pulseStudy's points, paperFigures' runs; adv43 k07, k21, adv44
    a43)."""
    n = 0
    while os.path.lexists("%s.%s%s" % (path, what, n or "")):
        n += 1
    return "%s.%s%s" % (path, what, n or "")


_DIRECTIVES = ("#include", "#sinclude", "#includeIfPresent")


def relativeOutside(case, folders=None):
    """The references of case's dictionaries to files outside it by a
    path that depends on where the case lies: an #include, #sinclude or
    #includeIfPresent of a relative path (from the including file's
    folder) or of one under $FOAM_CASE or <case>, and a 'file' entry (a
    tableFile's table) under $FOAM_CASE or <case>, that resolve outside
    case, whether the file is there or not. A copy of the case run
    elsewhere (pulseStudy's points, calibrateCell's work folder) reads
    another file there, or none (an #sinclude: silently; issue 19, adv45
    b15: a Maxwell branch the base case read through
    #sinclude "../../shared/override" was not read by the study's points,
    exit 0). [(file relative to case, the directive and its name, the
    path it resolves to from case)]; folders: those of case looked at
    (default every folder but the top, whose Allrun, README are not
    dictionaries)."""
    from . import foamDict
    real = os.path.realpath(case)
    found = []
    roots = [os.path.join(case, f) for f in folders] if folders else [
        os.path.join(case, f) for f in sorted(os.listdir(case))
        if os.path.isdir(os.path.join(case, f))
        and not os.path.islink(os.path.join(case, f))]
    for top in roots:
        for root, dirs, files in os.walk(top):
            dirs.sort()
            for f in sorted(files):
                full = os.path.join(root, f)
                if not os.path.isfile(full) or os.path.getsize(full) > 1 << 22:
                    continue
                with open(full, "rb") as h:
                    data = h.read()
                if b"#s" not in data and b"#include" not in data \
                        and b"file" not in data:
                    continue
                try:
                    toks = [x[0] for x in foamDict.tokens(
                        data.decode("utf-8"), full)]
                except (UnicodeDecodeError, foamDict.DictError):
                    continue        # not a dictionary we can read
                rel = os.path.relpath(full, case)
                for k in range(len(toks) - 1):
                    name = toks[k + 1]
                    if not (name.startswith('"') and name.endswith('"')):
                        if toks[k] != "file":
                            continue
                    name = name.strip('"')
                    caseVar = re.match(r"(\$\{?FOAM_CASE\}?|<case>)(/|$)",
                                       name)
                    if toks[k] in _DIRECTIVES:
                        if caseVar:
                            path = os.path.join(real, name[caseVar.end():])
                        elif name.startswith(("/", "$", "~", "<")):
                            continue            # absolute: the same file
                        else:
                            path = os.path.join(os.path.dirname(
                                os.path.realpath(full)), name)
                    elif toks[k] == "file" and caseVar:
                        path = os.path.join(real, name[caseVar.end():])
                    else:
                        continue
                    path = os.path.normpath(path)
                    if path != real and not path.startswith(real + os.sep):
                        found.append((rel, '%s "%s"' % (toks[k], name)
                                      if toks[k] != "file" else
                                      "file \"%s\"" % name, path))
    return found


def relativeOutsideProblem(case, copies, folders=None):
    """A message naming the references of relativeOutside(case, folders),
    '' if there are none; copies: where the tool runs its copies of the
    case (for the message)."""
    found = relativeOutside(case, folders)
    if not found:
        return ""
    return ("%s reads %s outside its folder by a path that depends on where "
            "the case lies: %s. %s, where %s another file or none. Nothing "
            "was run: give %s absolute (or copy the file into the "
            "case and include it from there)"
            % (case, "a file" if len(found) == 1 else "files", "; ".join(
                "%s: %s (here %s)" % f for f in found[:5])
               + ("; ..." if len(found) > 5 else ""), copies,
               "it would read" if len(found) == 1 else "they would read",
               "its path" if len(found) == 1 else "each path"))


def filesUnder(folder):
    """The files and links under folder: relative paths, a set."""
    found = set()
    for d, dirs, names in os.walk(folder):
        rel = os.path.relpath(d, folder)
        for n in names + [n for n in dirs
                          if os.path.islink(os.path.join(d, n))]:
            found.add(os.path.normpath(os.path.join(rel, n)))
    return found


def runIn(folder, command, log):
    """Run the shell command in folder, its stdout and stderr to
    folder/log (log itself if absolute); the wall time [s]. RunError if it
    fails, or if a run started there earlier still goes on."""
    checkNoEarlierRun(folder)
    t0 = time.time()
    path = os.path.join(folder, log)
    marker = os.path.join(folder, MARKER)

    def started(p):
        with open(marker, "w") as m:
            m.write("pgid %d\nhost %s\ncommand %s\nstarter %d %s\n"
                    % (p.pid, socket.gethostname(), command, os.getpid(),
                       _startTime(os.getpid())))

    try:
        with open(path, "w") as f:
            # ended, with what the shell started, on SIGTERM, SIGHUP,
            # SIGINT
            rc = signals.call(command, started=started, shell=True,
                              cwd=folder, stdout=f,
                              stderr=subprocess.STDOUT)
    finally:
        try:
            os.remove(marker)
        except OSError:
            pass
    if rc:
        raise RunError("'%s' failed (exit %d), see %s" % (command, rc, path))
    return time.time() - t0


def inParallel(nProcs, job, items):
    """[job(item) for item in items], nProcs at a time."""
    with concurrent.futures.ThreadPoolExecutor(nProcs) as pool:
        return list(pool.map(job, items))

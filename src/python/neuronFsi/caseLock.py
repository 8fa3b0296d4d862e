"""The case lock of our solvers (src/foamTools/caseLock.H), taken and read
by our Python tools: one run per case, whatever writes into it.

    with caseLock.held(case, "planeWave"):
        ...                         # writes into case

    caseLock.checkFree(case, "planeWave")  # reads a case: no run going on

The lock is the same file, <case>/.runLock, in the same format (pid, host,
executable, started, case), created the same way (O_CREAT | O_EXCL), and
a lock is stale under the same rules: of this host, and its process is
gone, runs another executable (the kernel's comm name, 15 characters,
begins the executable's name) or works on another case (its -case
option, else its working directory, links resolved). A stale lock is
replaced with a line saying so; what is not a lock (a directory, a FIFO,
an unreadable, empty or damaged file) and a lock of another host are never
taken over. So that a solver's caseLock can tell a Python tool's lock from
a stale one, the tool's process takes the tool's name as its comm name
(prctl PR_SET_NAME): "in use by planeWave (process ...)" both ways.

A case is also in use while a run that caseRuns.runIn started there (its
.caseRun marker) still has processes in it: an Allrun between two of its
solvers holds no .runLock (issue 19, adv34 n21: planeWave reported on a
run still going on without a word).

A tool started by a run that holds the lock (an Allrun: etc/RunFunctions
allrunLock, neuronFsi.allrunLock) takes it over, as the solvers do
(caseLock.H's underAncestor and takeOver): the lock names the tool, the
Allrun's lock kept below it as its lines each after "under ", and at the
tool's end it is given back (giveBack: the lines below, if that run still
goes on, else no lock). A lock whose process is over but whose taken-over
run goes on is that run's (holding). So a run's lock always names a live
process of it: an Allrun's shell killed alone leaves its solver or tool
named by the lock (issue 19, adv36 v69).

OpenFOAM's own utilities (blockMesh, decomposePar, foamListTimes, ...)
cannot take this lock: docs/reliability.md says so."""

import atexit
import contextlib
import ctypes
import errno
import fcntl
import os
import socket
import stat
import sys
import time

from . import caseRuns

FILE = ".runLock"
PID_MAX = 4194304               # Linux's PID_MAX_LIMIT


class CaseLockError(Exception):
    pass


def _notAFile(path):
    """What path is if it exists and is not a regular file, else ''."""
    try:
        m = os.lstat(path).st_mode
    except OSError:
        return ""
    for test, what in ((stat.S_ISDIR, "a directory"), (stat.S_ISFIFO,
                       "a FIFO"), (stat.S_ISSOCK, "a socket"),
                       (stat.S_ISCHR, "a device"), (stat.S_ISBLK,
                                                    "a device"),
                       (stat.S_ISLNK, "a symbolic link")):
        if test(m):
            return what
    return ""


# The largest lock file read [B]: a lock is a few lines per run taken over
# (a few hundred bytes); a larger file is no lock and is not read (adv48b
# g14: a .runLock of 8 GB was read whole). caseLock.H's maxLockBytes
MAX_LOCK_BYTES = 65536


def parse(text):
    """The fields of a lock's text as a dict (pid -1 if missing or not a
    process id); 'under': the text of the lock it took over (its lines
    "under <line>"), '' if none. caseLock.H's parse."""
    h = {"pid": -1, "host": "", "executable": "", "started": "", "case": "",
         "under": "", "readable": True, "whole": text.endswith("\n")}
    for line in text.split("\n"):
        key, _, value = line.strip().partition(" ")
        value = value.strip()
        if key == "pid":
            h["pid"] = int(value) if value.isdigit() and len(value) <= 7 \
                and 1 <= int(value) <= PID_MAX else -1
        elif key in ("host", "executable"):
            h[key] = value.split()[0] if value else ""
        elif key in ("started", "case"):
            h[key] = value
        elif key == "under":
            h["under"] += value + "\n"
    return h


def damage(h):
    """What makes lock h one that cannot be checked, '' if nothing:
    unreadable, naming no process, or cut short (a power loss or a full
    disk during its write: it must name its process, host, executable,
    start time and case and end with a whole line; adv44 a29: a lock cut after its
    first line was a live run "process 484 on host , started ;").
    caseLock.H's damage."""
    if h.get("tooLarge"):
        return ("far larger than a lock (%d bytes; a lock is a few lines, at "
                "most %d bytes): damaged or not a lock, not read"
                % (h["tooLarge"], MAX_LOCK_BYTES))
    if not h["readable"]:
        return "a file that cannot be read"
    if h["pid"] <= 0:
        return "empty or damaged (it names no process)"
    missing = [what for key, what in (("host", "its host"),
                                      ("executable", "its executable"),
                                      ("started", "its start time"),
                                      ("case", "its case"))
               if not h[key]]
    if not missing and h["whole"]:
        return ""
    return ("damaged: cut short (it names process %d but %s; a lock is cut "
            "by a power loss or a full disk while it is written)"
            % (h["pid"], "not " + ", ".join(missing) if missing
               else "its last line is cut"))


def readText(path):
    """The text of a lock file, None if it is not a regular file or
    cannot be read."""
    if _notAFile(path):
        return None
    try:
        if os.path.getsize(path) > MAX_LOCK_BYTES:
            return None
        with open(path, errors="replace") as f:
            return f.read(MAX_LOCK_BYTES + 1)
    except OSError:
        return None


def read(path):
    """The lock file's fields as a dict (parse; readable False if it
    cannot be read)."""
    text = readText(path)
    if text is None:
        h = parse("")
        h["readable"] = False
        try:
            if not _notAFile(path) \
                    and os.path.getsize(path) > MAX_LOCK_BYTES:
                h["tooLarge"] = os.path.getsize(path)
        except OSError:
            pass
        return h
    return parse(text)


def _running(pid):
    """The comm name of a live process, '' if none has that id."""
    st = caseRuns.procStat(pid)
    if st is None or st[1] in ("Z", "X"):
        return ""
    return st[0].strip() or "?"


def _runningCase(pid):
    """The identity (st_dev, st_ino) of the case directory a process works
    on: its -case option (relative to its working directory), else that
    directory, as stat sees it through /proc/PID/cwd; None when unknown.
    The identity, not the path: a run in the case seen through a bind
    mount (a container's view) has another path for the same directory
    (adv50a k10 (d): its lock taken for stale, an Allclean removed the
    results under the running solver)."""
    try:
        with open("/proc/%d/cmdline" % pid, "rb") as f:
            argv = f.read().decode(errors="replace").split("\0")
        d = "/proc/%d/cwd" % pid
        for i in range(1, len(argv) - 1):
            if argv[i] == "-case":
                # an absolute path in the process's own root
                c = argv[i + 1]
                d = (os.path.join("/proc/%d/root" % pid, c.lstrip("/"))
                     if c.startswith("/") else os.path.join(d, c))
        st = os.stat(d)
    except OSError:
        return None
    return (st.st_dev, st.st_ino)


def parent(pid):
    """The parent process id of pid (0 when unknown)."""
    st = caseRuns.procStat(pid)
    return st[2] if st is not None else 0


def isAncestor(pid, of):
    """True when pid is of or one of its ancestors."""
    seen = 0
    while of > 1 and seen < 1000:
        if of == pid:
            return True
        of = parent(of)
        seen += 1
    return False


def ownRun(h):
    """True when lock h is held by this process's own run: a live process
    of this host that is this process or one of its ancestors (the Allrun
    that started this tool: etc/RunFunctions allrunLock; caseLock.H's
    underAncestor)."""
    return (h["host"] == socket.gethostname() and h["pid"] > 0
            and bool(_running(h["pid"])) and isAncestor(h["pid"], os.getpid()))


def running(h):
    """True if the process of lock h is of this host and still runs its
    executable (caseLock.H's running)."""
    if h["host"] != socket.gethostname():
        return False
    comm = _running(h["pid"])
    return bool(comm) and comm == h["executable"][:len(comm)]


def holding(h):
    """The run that holds lock h: its process if it runs, else the first
    still running in the chain of locks it took over (a solver killed
    inside its live Allrun), else h (stale). caseLock.H's holding."""
    if h["host"] != socket.gethostname() or not h["under"] or running(h):
        return h
    below = holding(parse(h["under"]))
    return below if running(below) else h


def stale(h, case):
    """True if the run of lock h (of this host; give it holding(read(..)))
    is over: caseLock.H's rule."""
    if h["host"] != socket.gethostname():
        return False
    if not running(h):
        return True
    its = _runningCase(h["pid"])
    if its is None:
        return False
    try:
        st = os.stat(case)
    except OSError:
        return False
    return its != (st.st_dev, st.st_ino)


@contextlib.contextmanager
def directoryMutex(case):
    """An exclusive flock(2) on the case directory for the with-block
    (caseLock.H's directoryMutex): a lock is read, judged, removed and
    created under it, else two runs that find the same stale lock at once
    both remove it, the second removing the first's new lock, and both run
    (adv46b d67, d77). The kernel releases it when the descriptor closes
    or the process ends."""
    fd = os.open(case, os.O_RDONLY | os.O_DIRECTORY | os.O_CLOEXEC)
    try:
        fcntl.flock(fd, fcntl.LOCK_EX)
        yield
    finally:
        os.close(fd)


def lockText(pid, executable, case, started=None):
    """A lock's text for process pid (caseLock.H's lockText)."""
    return ("pid %d\nhost %s\nexecutable %s\nstarted %s\ncase %s\n"
            % (pid, socket.gethostname(), executable,
               started or time.strftime("%Y-%m-%dT%H:%M:%S"), case))


def spaceNote(path, err):
    """Why writing path failed, for a message: " (no space left on the
    device of '<dir>': N bytes free)" when its file system has less than
    1 MiB free or err is ENOSPC, else ": <strerror>" (caseLock.H's
    foamTools::spaceNote)."""
    d = os.path.dirname(os.path.abspath(path))
    try:
        st = os.statvfs(d)
        free = st.f_bavail*st.f_frsize
    except OSError:
        free = None
    if getattr(err, "errno", None) == errno.ENOSPC or \
            (free is not None and free < 1 << 20):
        return " (no space left on the device of '%s'%s)" % (
            d, ": %d bytes free" % free if free is not None else "")
    return ": %s" % (getattr(err, "strerror", None) or err)


def _replace(path, text, pid, what):
    """Write text to the lock path atomically (a temporary file renamed
    onto it); False if the rename fails."""
    tmp = "%s.%s.%d" % (path, what, pid)
    try:
        with open(tmp, "w") as f:
            f.write(text)
    except OSError:
        try:
            os.unlink(tmp)
        except OSError:
            pass
        raise
    try:
        os.rename(tmp, path)
    except OSError:
        os.unlink(tmp)
        return False
    return True


def takeOver(path, pid, executable, case, ancestor):
    """Take over the lock path of the run ancestor that started pid: the
    lock names pid, the one taken over kept as its "under" lines; False
    if the lock is gone or no longer that run's (caseLock.H's takeOver)."""
    text = readText(path)
    if not text or damage(parse(text)) \
            or holding(parse(text))["pid"] != ancestor:
        return False
    lock = lockText(pid, executable, case) + "".join(
        "under %s\n" % line for line in text.split("\n") if line)
    try:
        return _replace(path, lock, pid, "takeOver")
    except OSError as err:
        raise CaseLockError("cannot write the run lock %s%s. The case "
                            "directory must be writable"
                            % (path, spaceNote(path, err)))


def giveBack(path, pid):
    """At the end of the run of process pid, its lock given back: the
    lock it took over if that run still goes on, else none. Levels above
    pid's whose process is over go too; a lock a live process of another
    run holds is left (caseLock.H's giveBack)."""
    text = readText(path)
    if text is None:
        return
    h = parse(text)
    for _ in range(1000):
        if h["pid"] == pid:
            break
        if h["pid"] <= 0 or running(h) or not h["under"]:
            return
        h = parse(h["under"])
    if h["pid"] != pid:
        return
    try:
        if h["under"] and running(holding(parse(h["under"]))):
            if _replace(path, h["under"], pid, "giveBack"):
                return
        os.unlink(path)
    except OSError:
        pass


def _describe(h, path):
    return ("%s (process %d on host %s, started %s; lock file %s)"
            % (h["executable"] or "another run", h["pid"], h["host"],
               h["started"], path))


def inUse(case):
    """A sentence naming the run going on in case (its lock, or a run that
    caseRuns.runIn started there), or '' if none."""
    path = os.path.join(case, FILE)
    if os.path.lexists(path):
        h = read(path)
        if not damage(h):
            h = holding(h)
        what = _notAFile(path) or damage(h)
        if what:
            return ("its run lock %s is %s, not a lock that can be checked"
                    % (path, what))
        if not stale(h, case) and not ownRun(h):
            return "it is in use by " + _describe(h, path)
    m = caseRuns._marker(case)
    # the run of the marker is not this tool's own (an Allrun that runIn
    # started, running planeWave after its solver: the same process group)
    if m is not None and not (m[0] == os.getpgrp()
                              and m[1] == socket.gethostname()):
        pgid, host, command = m
        if host != socket.gethostname():
            return ("a run ('%s') was started there on host %s and may "
                    "still go on (%s)" % (command, host,
                                          os.path.join(case,
                                                       caseRuns.MARKER)))
        procs = caseRuns._groupIn(pgid, case)
        if procs:
            return ("a run started there ('%s') still goes on: process "
                    "group %d (%s)" % (command, pgid, ", ".join(
                        "%s pid %d" % (n, p) for p, n in procs[:4])))
    return ""


def checkFree(case, tool, option=None):
    """CaseLockError if a run goes on in case: what tool would read is
    not the run's result yet. option: the tool's option that asks for a
    report of the run so far, named in the message."""
    why = inUse(case)
    if why:
        raise CaseLockError(
            "the case %s is not finished: %s. Its results so far are "
            "partial; %s" % (
                os.path.realpath(case), why,
                "wait for the run to end, or give %s for a report of the "
                "run so far" % option if option else
                "wait for the run to end"))


def _setComm(name):
    """The process's comm name (ps, /proc/<pid>/comm), which a solver's
    caseLock compares with the lock's executable."""
    try:
        libc = ctypes.CDLL(None, use_errno=True)
        libc.prctl(15, ctypes.c_char_p(name.encode()[:15]), 0, 0, 0)
    except (OSError, AttributeError):
        pass


class held:
    """Context manager: the case lock of case, taken for tool (a
    CaseLockError naming the run holding it), released on leaving."""

    def __init__(self, case, tool):
        self.case = os.path.realpath(case)
        self.tool = tool
        self.path = os.path.join(case, FILE)
        self.taken = False

    def _create(self):
        try:
            fd = os.open(self.path, os.O_WRONLY | os.O_CREAT | os.O_EXCL,
                         0o644)
        except FileExistsError:
            return False
        except OSError as err:
            raise CaseLockError("cannot create the run lock %s%s. The "
                                "case directory must be writable"
                                % (self.path, spaceNote(self.path, err)))
        try:
            with os.fdopen(fd, "w") as f:
                f.write(lockText(os.getpid(), self.tool, self.case))
        except OSError as err:
            # a full disk: the write or the flush at close fails, naming
            # no file (adv38 x55: "a file could not be written or read:
            # No space left on device"); the empty lock removed
            try:
                os.unlink(self.path)
            except OSError:
                pass
            raise CaseLockError("cannot write the run lock %s%s. The case "
                                "directory must be writable, with room for "
                                "the lock" % (self.path,
                                              spaceNote(self.path, err)))
        return True

    def __enter__(self):
        if not os.path.isdir(self.case):
            raise CaseLockError("the case %s is not a directory"
                                % self.case)
        _setComm(self.tool)
        why = inUse(self.case)
        if why and not why.startswith("it is in use") \
                and not why.startswith("its run lock"):
            raise CaseLockError("the case %s is in use: %s. One run per "
                                "case: wait for it to end" % (self.case,
                                                              why))
        with directoryMutex(self.case):
            return self._enterLocked()

    def _enterLocked(self):
        for attempt in range(2):
            if self._create():
                self.taken = True
                atexit.register(self._release)
                return self
            h = read(self.path)
            if h["readable"] and damage(h):
                time.sleep(0.5)        # a run starting: not written yet
                h = read(self.path)
            what = _notAFile(self.path) or damage(h)
            if not what:
                h = holding(h)
            if ownRun(h):
                if h["pid"] == os.getpid():
                    return self        # this process holds it already
                # its Allrun's lock, taken over until this tool's end
                if not takeOver(self.path, os.getpid(), self.tool,
                                self.case, h["pid"]):
                    continue
                self.taken = True
                atexit.register(self._release)
                return self
            if what:
                raise CaseLockError(
                    "the run lock %s of the case %s is %s, not a lock this "
                    "run can check. If no run of this case is going on (or"
                    " starting), remove it; otherwise wait for that run to "
                    "end" % (self.path, self.case, what))
            if attempt > 0 or not stale(h, self.case):
                raise CaseLockError(
                    "the case %s is in use by %s. One run per case: wait "
                    "for that run to end or stop it, or copy the case. If "
                    "that run is over (a run on another host cannot be "
                    "checked from here), remove %s"
                    % (self.case, _describe(h, self.path), self.path))
            print("%s: removing the stale run lock %s of %s (process %d on "
                  "%s, started %s; no longer running, or running another "
                  "case)" % (self.tool, self.path, h["executable"], h["pid"],
                             h["host"], h["started"]), file=sys.stderr)
            try:
                os.unlink(self.path)
            except FileNotFoundError:
                pass
        raise CaseLockError("cannot take the run lock %s: it changed twice "
                            "while this run looked at it (other runs "
                            "starting or ending); start again" % self.path)

    def _release(self):
        if self.taken:
            self.taken = False
            giveBack(self.path, os.getpid())

    def __exit__(self, *exc):
        self._release()
        return False

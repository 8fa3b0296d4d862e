"""The main of every Python script of the project (plots, utilities,
benchmarks): an error that is the input's or the environment's becomes one
line, "<script>: error: <message>", and exit 1, never a traceback (adv33
c13, sh25: a reader's ColumnFileError uncaught in a plot script; cc19: a
binary of the project missing from PATH).

    from neuronFsi import script
    script.guard()          # before anything else runs

What is the input's or the environment's: an exception of a neuronFsi
module (each reader raises its own class, whose message names the file
and the entry), a file that cannot be opened or read (OSError: the file is
named), a program that is not on PATH (the project not built or its
etc/bashrc not sourced). Any other exception is a bug of the script and
keeps its traceback.

A script run without the project's environment cannot import neuronFsi
(adv33 pl01: ModuleNotFoundError): its first neuronFsi import is

    try:
        from neuronFsi import script
    except ImportError:
        sys.exit("<script>: error: the project's Python package neuronFsi "
                 "is not found: source the project's etc/bashrc first")
    script.guard()
"""

import contextlib
import errno
import os
import sys


def _ours(err):
    """Whether err was raised by a reader of neuronFsi (its class is)."""
    return any(c.__module__.split(".")[0] == "neuronFsi"
               for c in type(err).__mro__)


def _writtenFile(tb):
    """The file an OSError without a file name was raised on (a full disk:
    write() or the flush at close name none; adv38 x55, a write outside
    writing()): the innermost file object open for writing among the
    locals of the frames of its traceback tb (a `with open(...) as f`
    body, a writer's close), as (label, path); None if none is found."""
    import io
    frames = []
    while tb is not None:
        frames.append(tb.tb_frame)
        tb = tb.tb_next
    for frame in reversed(frames):
        for v in list(frame.f_locals.values()):
            if isinstance(v, (io.TextIOWrapper, io.BufferedWriter,
                              io.BufferedRandom, io.FileIO)) \
                    and isinstance(getattr(v, "name", None), str) \
                    and any(m in getattr(v, "mode", "") for m in "wax+"):
                return v.name, v.name
    return None


def _fullOutput(err):
    """(label, path) of the standard output or error when it is a regular
    file on a device with less than 1 MiB free and err is a full disk's
    (adv38 x55: planeWave's print to its log on a full file system raised
    ENOSPC, no file named); None otherwise."""
    import stat
    if err.errno not in (errno.ENOSPC, errno.EDQUOT):
        return None
    for fd, what in ((1, "the standard output"), (2, "the standard error")):
        try:
            if not stat.S_ISREG(os.fstat(fd).st_mode):
                continue
            s = os.fstatvfs(fd)
            if s.f_bavail*s.f_frsize >= 1 << 20:
                continue
            path = os.readlink("/proc/self/fd/%d" % fd)
        except OSError:
            continue
        return "%s (%s)" % (what, path), path
    return None


def _spaceNote(name):
    """" (N bytes free on the device of '<dir>')" for the file name, "" if
    not known."""
    d = os.path.dirname(os.path.abspath(name))
    try:
        s = os.statvfs(d)
    except OSError:
        return ""
    return " (%d bytes free on the device of '%s')" % (s.f_bavail*s.f_frsize,
                                                       d)


def message(err, tb=None):
    """The one-line message of an input's or environment's error, or None
    for any other exception; tb: its traceback (names the file an OSError
    without a file name was written to, _writtenFile)."""
    if _ours(err):
        return str(err)
    if isinstance(err, FileNotFoundError) and err.filename and \
            os.sep not in str(err.filename):
        # subprocess: a program name, not a path
        return ("the program '%s' is not found on PATH: build the project "
                "(./Allwmake) and source its etc/bashrc first"
                % err.filename)
    if isinstance(err, OSError) and err.filename:
        return "%s: %s" % (err.filename, err.strerror or err)
    if isinstance(err, OSError) and err.errno:
        # no file named (adv33 x12: a full disk inside matplotlib's save;
        # adv38 x55: planeWave on a full disk): the file found from the
        # traceback, with the space left on its device
        found = _writtenFile(tb) or _fullOutput(err)
        if found:
            return "%s: %s%s" % (found[0], err.strerror or err,
                                 _spaceNote(found[1]) if err.errno in (
                                     errno.ENOSPC, errno.EDQUOT) else "")
        return "a file could not be written or read: %s" \
            % (err.strerror or err)
    return None


class OutputLinkError(Exception):
    """A file a script would write lies in a folder of a case reached
    through a symbolic link leaving that case; the message names both."""


def _caseOf(folder):
    """The case folder holding folder (the nearest folder at or above it,
    by its path as given, links not resolved, that holds system/), None if
    none."""
    d = os.path.abspath(folder)
    while True:
        if os.path.isdir(os.path.join(d, "system")):
            return d
        up = os.path.dirname(d)
        if up == d:
            return None
        d = up


def checkOutputFolder(path):
    """An OutputLinkError if path's folder lies in a case (_caseOf) but its
    real path leaves the case: a folder of the case (postProcessing/,
    postProcessing/planeWave, ...) that is a symbolic link to another
    case's or a shared folder (adv54 v03: planeWave in case B, whose
    postProcessing/planeWave was a link to A's, replaced A's reference.dat
    and measures; the C++ applications refuse such folders since fix19j,
    caseLock::outputLinksLeaving)."""
    folder = os.path.dirname(os.path.abspath(path))
    case = _caseOf(folder)
    if case is None:
        return
    real, realCase = os.path.realpath(folder), os.path.realpath(case)
    if real != realCase and not real.startswith(realCase + os.sep):
        raise OutputLinkError(
            "%s: its folder %s is reached through a symbolic link leaving "
            "the case %s (its real path is %s): writing there would write "
            "into another case's folder or one shared with it. Nothing was "
            "written; replace the link by a folder of the case"
            % (path, folder, case, real))


@contextlib.contextmanager
def _inPlace(path, mode):
    if os.path.islink(path) and "w" in mode:
        os.remove(path)
    try:
        with open(path, mode) as f:
            yield f
    except OSError as err:
        if err.filename or not err.errno:
            raise
        raise OSError(err.errno, err.strerror, path) from err


@contextlib.contextmanager
def writing(path, mode="w"):
    """open(path, mode) for writing, as a context manager: an OSError
    without a file name while the file is written or closed (a full disk:
    ENOSPC comes from write() or the flush at close, which name no file)
    is raised again naming path, so that message() names the file that
    could not be written (adv38 x55: planeWave on a full disk said "a file
    could not be written or read"). A file written whole (mode "w") is
    written by replacement (replacing): a symbolic link at path is
    replaced by the file, never written through (adv44 a17: calibrateCell
    wrote its results over the user's shared files outside the case), a
    file hard-linked with another case's copy is not written through
    (adv54 n14: planeWave in a copy made by cp -al replaced the original's
    reference.dat), and a write that fails leaves path as it was (adv53
    l09: a 0-byte blockMeshDict on a full disk). A device (/dev/null) is
    written in place. A folder of a case reached through a link leaving
    the case is refused (checkOutputFolder)."""
    checkOutputFolder(path)
    if "w" in mode and (os.path.islink(path) or not os.path.exists(path)
                        or os.path.isfile(path)):
        with replacing(path, mode) as f:
            yield f
        return
    with _inPlace(path, mode) as f:
        yield f


@contextlib.contextmanager
def replacing(path, mode="w"):
    """writing(path, mode) by replacement: the text goes to a new temporary
    file beside path (path.tmp<pid>, created exclusively: never through a
    link), renamed over path when complete, with the permissions of the
    file it replaces. A symbolic link at path is replaced by the file,
    never written through (adv44 a17: calibrateCell wrote its results over
    the user's shared files outside the case that links of the case
    pointed to), and a write that fails leaves path as it was (the
    temporary file is removed)."""
    checkOutputFolder(path)
    tmp = "%s.tmp%d" % (path, os.getpid())
    fd = os.open(tmp, os.O_WRONLY | os.O_CREAT | os.O_EXCL
                 | getattr(os, "O_NOFOLLOW", 0), 0o666)
    os.close(fd)
    try:
        if os.path.isfile(path) and not os.path.islink(path):
            os.chmod(tmp, os.stat(path).st_mode & 0o7777)
        with _inPlace(tmp, mode) as f:
            yield f
        os.replace(tmp, path)
    except BaseException:
        if os.path.lexists(tmp):
            os.remove(tmp)
        raise


def saveFigure(fig, path, **kw):
    """fig.savefig(path, **kw) through writing(path): by replacement, never
    through a hard or symbolic link (adv54 n14: plotBlast.py in a copy
    made by cp -al rewrote the original's fig10.png)."""
    fmt = kw.pop("format", None) or \
        os.path.splitext(path)[1].lstrip(".").lower() or None
    with writing(path, "wb") as f:
        fig.savefig(f, format=fmt, **kw)


def _hook(name):
    def hook(kind, err, tb):
        text = message(err, tb) if isinstance(err, Exception) else None
        if text is None:
            sys.__excepthook__(kind, err, tb)
        else:
            sys.stderr.write("%s: error: %s\n" % (name, text))
    return hook


def arguments(n, usage, name=None):
    """sys.argv[1:] when it holds at least n arguments; else the usage as
    one line "<name>: error: usage: <usage>" on stderr, exit 1 (adv53 u12:
    the analysis scripts without their arguments raised IndexError
    tracebacks). name: the script's (default: its file name)."""
    if len(sys.argv) - 1 < n:
        sys.exit("%s: error: usage: %s" % (
            name or os.path.basename(sys.argv[0]), usage))
    return sys.argv[1:]


def labelled(arg, what="LABEL=CASE", name=None):
    """(label, value) of a command-line argument "LABEL=VALUE"; else one
    line naming the argument and the form, exit 1 (adv53 u12: "not enough
    values to unpack" tracebacks of the ladder scripts)."""
    label, eq, value = arg.partition("=")
    if not eq or not label or not value:
        sys.exit("%s: error: argument '%s' is not of the form %s" % (
            name or os.path.basename(sys.argv[0]), arg, what))
    return label, value


def guard(name=None):
    """From here on, an input's or environment's error that the script
    does not catch is printed as one line "<name>: error: <message>" on
    stderr (exit 1, as after any uncaught exception) instead of a
    traceback; other exceptions keep theirs (see the module). name: the
    script's (default: its file name)."""
    sys.excepthook = _hook(name or os.path.basename(sys.argv[0]))

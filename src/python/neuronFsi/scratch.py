"""Scratch copies of case folders: a benchmark, a test or a utility runs a
tutorial's inputs in a folder of its own, so that running never touches
the tracked case (and meshes made there are made again)."""

import fcntl
import fnmatch
import os
import shutil
import socket
import sys
import time


class ScratchError(Exception):
    """An output folder a script may not use; the message names it."""


MARKER = ".scratchFolder"

# The lock a script holds on its output folder for its whole run (flock on
# this file in the folder, naming pid, host, start and script): a second
# script refuses the folder while it is held (issue 19, adv52 p01b (b): a
# second restartDigits.sh emptied the first's folder between the first's
# solver runs, when no run lock was there). The shell scripts hold it with
# flock(1) on a descriptor of their own shell (etc/scratchFolder) and tell
# the Python side through LOCKED_ENV.
LOCK = ".scratchLock"
LOCKED_ENV = "NEURONFSI_SCRATCH_LOCKED"
_held = {}

# The entries a run of a case leaves in its folder (the tutorials'
# .gitignore: inputs, times, logs, results, plots, our run records): the
# entry "@case" of outputFolder stands for them, "NAME/@case" for a
# sub-folder NAME holding a case. A marked folder is emptied only if what
# it holds matches (adv52 o09 (d): a marked folder without entries was
# emptied whatever it held, a user's analysis.txt added to it removed;
# (b): a user's file inside the script's own case folder removed)
CASE_ENTRIES = ("0", "0.orig", "constant", "system", "[0-9]*", "-[0-9]*",
                ".[0-9]*", "processor*", "postProcessing", "solid", "VTK",
                "log*", "*.foam", "*.OpenFOAM", ".runLock",
                ".allrunOptions", ".allrunLock*", "Allrun", "Allclean",
                "README.md", "*.png", "*.h5", "*.xmf", "*.calibrated",
                "results.md", "*.incomplete", "*.overwritten", MARKER)


def _foreign(path, names, entries):
    """The names of path (a folder) that match no pattern of entries
    ("@case": CASE_ENTRIES; "NAME/@case": a folder NAME whose own names
    match CASE_ENTRIES, else "NAME/<name>" is foreign)."""
    patterns, nested = [], []
    for e in entries:
        if e == "@case":
            patterns.extend(CASE_ENTRIES)
        elif e.endswith("/@case"):
            nested.append(e[:-len("/@case")])
        else:
            patterns.append(e)
    foreign = []
    for n in names:
        if n in (MARKER, LOCK) \
                or any(fnmatch.fnmatchcase(n, e) for e in patterns):
            continue
        if any(fnmatch.fnmatchcase(n, e) for e in nested):
            sub = os.path.join(path, n)
            if os.path.isdir(sub) and not os.path.islink(sub):
                foreign.extend(os.path.join(n, m) for m in
                               _foreign(sub, sorted(os.listdir(sub)),
                                        ("@case",)))
                continue
        foreign.append(n)
    return foreign


def _marker(path):
    """(script, record) of path's marker: the script's name (None without
    a marker) and {relative path: (size, mtime_ns)} of the files the
    script's run left there (recordOutputs; empty for a run killed before
    its end; None for a marker of an earlier version, without a record)."""
    try:
        with open(os.path.join(path, MARKER), errors="replace") as f:
            lines = f.read().split("\n")
    except OSError:
        return None, None
    record = None
    if len(lines) > 1 and lines[1] == "record":
        record = {}
        for line in lines[2:]:
            parts = line.split(" ", 3)
            if len(parts) == 4 and parts[0] == "file":
                try:
                    record[parts[3]] = (int(parts[1]), int(parts[2]))
                except ValueError:
                    pass
    return lines[0].strip(), record


def _unrecorded(path, record):
    """The files under path (its marker and lock but) that are not in
    record as they are now (another size or time: changed since), and
    links: what the earlier run did not leave there."""
    foreign = []
    for d, dirs, files in os.walk(path):
        for n in files + [x for x in dirs
                          if os.path.islink(os.path.join(d, x))]:
            full = os.path.join(d, n)
            rel = os.path.relpath(full, path)
            if rel in (MARKER, LOCK):
                continue
            try:
                st = os.lstat(full)
            except OSError:
                continue
            if record.get(rel) != (st.st_size, st.st_mtime_ns):
                foreign.append(rel)
    return sorted(foreign)


def recordOutputs(path):
    """Record in path's marker every file the script's run left under it
    (relative path, size, modification time in ns): the next run of the
    script empties the folder only if it holds these files unchanged and
    nothing else (adv53 u10). Called at the script's end (outputFolder
    registers it with atexit; etc/scratchFolder's EXIT trap)."""
    marker = os.path.join(path, MARKER)
    owner, _ = _marker(path)
    if owner is None:
        return
    lines = [owner, "record"]
    for d, dirs, files in os.walk(path):
        for n in sorted(files):
            full = os.path.join(d, n)
            rel = os.path.relpath(full, path)
            if rel in (MARKER, LOCK) or "\n" in rel:
                continue
            try:
                st = os.lstat(full)
            except OSError:
                continue
            lines.append("file %d %d %s" % (st.st_size, st.st_mtime_ns, rel))
    tmp = "%s.tmp%d" % (marker, os.getpid())
    with open(tmp, "w") as f:
        f.write("\n".join(lines) + "\n")
    os.replace(tmp, marker)


def checkOutputFolder(script, path, entries=()):
    """outputFolder's judgement without removing anything: ScratchError if
    path may not be used; True if it holds an earlier output of script
    (to be emptied), False if it is absent or empty."""
    if os.path.islink(path) or (os.path.lexists(path)
                                and not os.path.isdir(path)):
        raise ScratchError("%s exists and is not a folder (a file or a "
                           "link): give a new or an empty folder. Nothing "
                           "was removed." % path)
    if not os.path.isdir(path):
        return False
    names = sorted(n for n in os.listdir(path) if n != LOCK)
    if not names:
        return False
    owner, record = _marker(path)
    if owner == script and record is not None:
        # what the earlier run left, file by file (adv53 u10: a user's
        # logbook.txt, README.md, myFigure.png, postProcessing/
        # myAnalysis.txt matched the case's name patterns and were removed)
        foreign = _unrecorded(path, record)
    elif owner == script:
        foreign = _foreign(path, names, entries) if entries else []
    else:
        foreign = names
    if foreign:
        raise ScratchError(
            "%s exists and holds %d file(s) or folder(s) that no earlier "
            "run of %s made there (%s%s): give a new or an empty folder, or "
            "move them away. Nothing was removed."
            % (path, len(foreign), script, " ".join(foreign[:5]),
               " ..." if len(foreign) > 5 else ""))
    return True


def _pidAlive(pid):
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except (PermissionError, OverflowError, ValueError):
        return True
    return True


def lockText(path):
    """The lock file's lines as one text ("pid 123, host h, started ...,
    script s"), "" if it cannot be read."""
    try:
        with open(os.path.join(path, LOCK), errors="replace") as f:
            return ", ".join(line.strip() for line in f if line.strip())
    except OSError:
        return ""


def lockFolder(script, path):
    """Take the output folder path's lock (LOCK, flock) for this process's
    whole run, path made if it is not there. A lock held by another live
    script is a ScratchError naming it (pid, host, start, script); one
    left by a script that ended (flock is released with its process) is
    taken over, said on stderr when it names another process of this
    host. Nothing is done when this process holds it already, or when the
    shell script that runs this one holds it (LOCKED_ENV)."""
    real = os.path.realpath(path)
    if real in _held or os.environ.get(LOCKED_ENV) and \
            os.path.realpath(os.environ[LOCKED_ENV]) == real:
        return
    os.makedirs(path, exist_ok=True)
    lock = os.path.join(path, LOCK)
    fd = os.open(lock, os.O_RDWR | os.O_CREAT | getattr(os, "O_NOFOLLOW", 0)
                 | getattr(os, "O_CLOEXEC", 0), 0o644)
    try:
        fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
    except OSError:
        os.close(fd)
        raise ScratchError(
            "%s is in use by another script's run (its lock %s: %s): "
            "emptying it would remove that run's files under it. Wait for "
            "it to end, or give another folder. Nothing was removed."
            % (path, lock, lockText(path) or "unreadable"))
    old = lockText(path)
    fields = dict(item.split(" ", 1) for item in old.split(", ")
                  if " " in item)
    try:
        pid = int(fields.get("pid", "0"))
    except ValueError:
        pid = 0
    if pid and pid != os.getpid() \
            and fields.get("host") == socket.gethostname() \
            and not _pidAlive(pid):
        print("%s: note: taking over the stale lock of %s (%s: that "
              "process has ended)" % (script, path, old), file=sys.stderr)
    os.ftruncate(fd, 0)
    os.write(fd, ("pid %d\nhost %s\nstarted %s\nscript %s\n" % (
        os.getpid(), socket.gethostname(),
        time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime()), script)).encode())
    _held[real] = fd


def outputFolder(script, path, entries=()):
    """path made ready, empty but for its marker, for the outputs of
    script (a test's, a benchmark's or a study's folder given on its
    command line, or one it names inside such a folder). A path that does
    not exist or is an empty folder is used. A folder an earlier run of
    script made (its marker .scratchFolder names script) is emptied if it
    holds only entries matching a pattern of entries (any name when none
    are given). Anything else - a user's folder, a marked folder holding
    a file the script does not write, a file or a link - is refused
    (ScratchError naming what it holds): nothing is removed (issue 19,
    adv51 n01: eleven scripts removed a user's folder given as or inside
    their output folder, rm -rf / shutil.rmtree). Returns path. The
    shell scripts' etc/scratchFolder runs this."""
    # the folder's lock first, held for the script's run (adv52 p01b (b)):
    # a folder judged and emptied while another script still uses it is
    # what the lock prevents; on a refusal below the lock file this made
    # in a user's folder is removed again
    made = not os.path.lexists(path)
    hadLock = os.path.lexists(os.path.join(path, LOCK))
    if not os.path.islink(path) and (made or os.path.isdir(path)):
        lockFolder(script, path)
    try:
        emptied = checkOutputFolder(script, path, entries)
    except ScratchError:
        if not hadLock and os.path.realpath(path) in _held:
            os.close(_held.pop(os.path.realpath(path)))
            os.remove(os.path.join(path, LOCK))
        raise
    if emptied:
        # never under a run going on (adv52 p02 (b): a second gapStudy.sh
        # emptied its earlier folder under the first's running solver)
        from .allrunLock import busyUnder
        busy = busyUnder([path])
        if busy:
            raise ScratchError(
                "%s holds a run going on (%s: %s): it would be removed "
                "under that run. Wait for it to end or stop it, or give "
                "another folder. Nothing was removed."
                % (path, busy[0][0], busy[0][1]))
        # emptied but for its lock
        for n in os.listdir(path):
            if n == LOCK:
                continue
            full = os.path.join(path, n)
            if os.path.isdir(full) and not os.path.islink(full):
                shutil.rmtree(full)
            else:
                os.remove(full)
    os.makedirs(path, exist_ok=True)
    # the record starts empty: a run killed before its end (no record of
    # its own) vouches for nothing, and its folder is refused rather than
    # judged by name patterns (adv53 l33: a killed runPreview.sh's folder
    # with a user's logbook.txt added was emptied)
    with open(os.path.join(path, MARKER), "w") as f:
        f.write(script + "\nrecord\n")
    # what the run leaves, recorded at its end (a shell script's by its
    # EXIT trap, etc/scratchFolder)
    if not os.environ.get(LOCKED_ENV):
        import atexit
        atexit.register(recordOutputs, path)
    return path


def copyInputs(src, dst, names, ignore=()):
    """Copy the entries `names` (folders and files) of the case src into
    the new folder dst (or one outputFolder made: empty but for its
    marker), without what matches a pattern of ignore at any depth
    (meshes that the case's Allrun makes again)."""
    if os.path.isdir(dst) and set(os.listdir(dst)) <= {MARKER, LOCK}:
        pass
    else:
        os.makedirs(dst)
    for name in names:
        s = os.path.join(src, name)
        if os.path.isdir(s):
            shutil.copytree(s, os.path.join(dst, name),
                            ignore=shutil.ignore_patterns(*ignore))
        else:
            shutil.copy(s, dst)


def main(argv=None):
    """Command line for shell scripts: python3 -m neuronFsi.scratch SRC DST
    NAME... [--ignore PATTERN...]; python3 -m neuronFsi.scratch
    --outputFolder SCRIPT DIR [ENTRY...] (outputFolder)"""
    import argparse
    import sys
    args = sys.argv[1:] if argv is None else list(argv)
    if args[:1] == ["--record"]:
        for d in args[1:]:
            try:
                recordOutputs(d)
            except OSError as e:
                sys.exit("scratch --record: %s: %s" % (e.filename or d,
                                                       e.strerror))
        return 0
    if args[:1] == ["--outputFolder"]:
        if len(args) < 3:
            sys.exit("usage: python3 -m neuronFsi.scratch --outputFolder "
                     "SCRIPT DIR [ENTRY...]")
        try:
            outputFolder(args[1], args[2], args[3:])
        except ScratchError as e:
            sys.exit("%s: error: %s" % (args[1], e))
        except OSError as e:
            sys.exit("%s: error: %s: %s" % (args[1], e.filename or args[2],
                                            e.strerror))
        return 0
    p = argparse.ArgumentParser(
        prog="python3 -m neuronFsi.scratch",
        description="Copy a case's inputs into a new scratch folder.")
    p.add_argument("src", help="the case folder to copy from")
    p.add_argument("dst", help="the new folder (must not exist)")
    p.add_argument("names", nargs="+",
                   help="entries of src to copy (e.g. 0.orig constant system Allrun)")
    p.add_argument("--ignore", nargs="*", default=(),
                   help="patterns left out at any depth (e.g. polyMesh '*.msh')")
    a = p.parse_args(argv)
    if os.path.exists(a.dst):
        p.error("%s exists: give a new folder" % a.dst)
    for name in a.names:
        if not os.path.exists(os.path.join(a.src, name)):
            p.error("%s has no %s" % (a.src, name))
    copyInputs(a.src, a.dst, a.names, a.ignore)


if __name__ == "__main__":
    main()

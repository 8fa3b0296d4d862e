"""The digests of our text results, verified before a result is measured
(issue 19 class 5; adv52 p06b, p31: a hand-edited probe log, planeWave's
reference.dat and the indentation's peaks.dat were measured and plotted as
if they were ours).

What a writer records (the project's one file digest, FNV-1a 64-bit over
the bytes, continued: src/foamTools/fileDigest.H):

- a sidecar `<file>.fnv1a64` beside a text result we write line by line:
  one line "<bytes> <digest>" after each line of the file, the digest of
  its first <bytes> bytes (cellIndentationFoam's force.dat and peaks.dat,
  appended with each row and flushed with it; planeWave's reference.dat,
  written whole: writeSidecar). The digests are cumulative, so the first
  line whose digest differs is the first edited line.
- the commit markers `<time>/.writeCommitted` of the OpenFOAM solvers: at
  every write time a line "log <digest> <bytes> postProcessing/<log>/
  <start>/<file>" for every log a restart continues (the probes,
  movingMeshProbes and fieldMinMax function objects, cellBlastFoam's fsi,
  solidProbes, solidInterfaces; src/foamTools/restartLogs.H). Those logs
  are written by OpenFOAM's function objects, whose writes we do not hold:
  the digests are per write interval, and an edit is named by the first
  line of the first interval whose bytes differ.

check(path) verifies a file against whichever it has and raises a
DigestError naming the file and the first line that is not as written; a
file with neither (made by hand, or written before this version) is
refused too, unless the caller's explicit option says to measure it as it
is (handMade=True). Rows written after the last record (a run killed
between write times, or still going) are not covered: check returns their
first line (None if there are none)."""

import glob
import os

from . import options

SUFFIX = ".fnv1a64"
BASIS = 0xcbf29ce484222325
_PRIME = 0x100000001b3
_MASK = (1 << 64) - 1


# The measuring script's explicit option to measure files without (or not
# matching) their digests, and whether the user gave it (measuring()):
# the readers' check() then passes them
_option = None
_handMade = False
# The script's option to measure a run so far (planeWave -partial): rows
# after the run's last record are measured (measuringPartial())
_partial = False
# Files verified in this process, by their state (path, device, inode,
# size, modification time) and records: a script reading one log through
# several readers verifies it once
_verified = {}


def measuring(option, given):
    """Set by a script that measures results: the name of its option that
    accepts hand-made files (named in the refusals) and whether the user
    gave it."""
    global _option, _handMade
    _option, _handMade = option, bool(given)


def _give(option):
    """The end of a refusal: the script's option that measures a file as it
    is, or, for a script without one (a benchmark, a test), the tools that
    have it."""
    if option:
        return "give %s to measure it as it is" % option
    return ("measure it as it is with a tool whose option accepts hand-made"
            " files (planeWave, plotBlast.py, plotIndentation.py "
            "-acceptHandMade): this script has none")


_partialOption = None


def measuringPartial(given, option="-partial"):
    """Set by a script whose explicit option measures a run so far (planeWave,
    plotBlast.py -partial): the rows written after its last record are
    measured (uncoveredRows passes them); option is named in the
    refusals."""
    global _partial, _partialOption
    _partial = bool(given)
    _partialOption = option


class DigestError(Exception):
    """A result that is not as its writer wrote it, or has no digest; the
    message names the file and the line."""


def add(h, data):
    """Continue the FNV-1a 64-bit digest h over the bytes data (that of
    fileDigest::add)."""
    for b in data:
        h = ((h ^ b) * _PRIME) & _MASK
    return h


def hexText(h):
    """The digest as fileDigest::hex writes it: lower-case hex digits,
    without leading zeros (compared as numbers: check)."""
    return "%x" % h


def writeSidecar(path):
    """Write path's sidecar path + SUFFIX: one "<bytes> <digest>" line
    after each of its lines (for a file written whole: planeWave's
    reference.dat), by replacement."""
    from . import script
    with open(path, "rb") as f:
        data = f.read()
    h, n, out = BASIS, 0, []
    for line in data.splitlines(keepends=True):
        h = add(h, line)
        n += len(line)
        out.append("%d %s\n" % (n, hexText(h)))
    with script.replacing(path + SUFFIX) as f:
        f.write("".join(out))


def _sidecarRecords(path):
    side = path + SUFFIX
    if not os.path.isfile(side):
        return None
    refusal = options.readRefusal(side, options.TABLE_LIMIT, "digest file")
    if refusal:
        raise DigestError(refusal)
    records = []
    with open(side, errors="replace") as f:
        lines = f.read().split("\n")
    # the last line without its end: cut by a kill while the sidecar was
    # written (its rows then are the uncovered tail), not a damage
    for k, line in enumerate(lines[:-1], 1):
        parts = line.split()
        try:
            records.append((int(parts[0]), int(parts[1], 16), side, k))
            if len(parts) != 2 or len(parts[1]) > 16:
                raise ValueError
        except (ValueError, IndexError):
            raise DigestError("%s, line %d: not a line '<bytes> <digest>' "
                              "of the digests of %s (damaged or edited)"
                              % (side, k, path))
    return records


def _caseOf(path):
    """(case, path relative to it) of a file under <case>/postProcessing/,
    (None, None) otherwise."""
    full = os.path.abspath(path)
    parts = full.split(os.sep)
    if "postProcessing" not in parts:
        return None, None
    k = len(parts) - 1 - parts[::-1].index("postProcessing")
    case = os.sep.join(parts[:k]) or os.sep
    return case, "/".join(parts[k:])


def _markerRecords(path):
    """The commit markers' "log" lines of path: [(bytes, digest, marker,
    line)], None if no marker records it."""
    case, rel = _caseOf(path)
    if case is None:
        return None
    records = []
    markers = glob.glob(os.path.join(case, "*", ".writeCommitted")) \
        + glob.glob(os.path.join(case, "processor0", "*", ".writeCommitted"))
    for m in sorted(markers):
        # time directories only (not a <time>.incomplete or .overwritten
        # one moved aside, whose digests are of an earlier run's logs)
        try:
            float(os.path.basename(os.path.dirname(m)))
        except ValueError:
            continue
        try:
            with open(m, errors="replace") as f:
                for k, line in enumerate(f, 1):
                    parts = line.rstrip("\n").split(" ", 3)
                    if len(parts) == 4 and parts[0] == "log" \
                            and parts[3] == rel:
                        try:
                            records.append((int(parts[2]),
                                            int(parts[1], 16), m, k))
                        except ValueError:
                            pass
        except OSError:
            pass
    return records or None


def _isTime(name):
    try:
        float(name)
        return True
    except ValueError:
        return False


def _reconstructedNote(path):
    """", or its run's processor*/ folders, which hold the commit markers
    of a parallel run, were removed after reconstructPar" when path's case
    has time folders, none with a commit marker, and no processor0/ (adv54
    n33: the usual clean-up of a parallel run); "" otherwise."""
    case, rel = _caseOf(path)
    if case is None:
        return ""
    if os.path.isdir(os.path.join(case, "processor0")):
        # a serial run decomposed afterwards (decomposePar copies no commit
        # marker into processor*/) whose serial times were removed (adv54
        # n33 (b))
        ranks = [d for d in glob.glob(os.path.join(case, "processor0", "*"))
                 if _isTime(os.path.basename(d))]
        serial = [d for d in glob.glob(os.path.join(case, "*"))
                  if _isTime(os.path.basename(d))]
        if ranks and not any(os.path.isfile(os.path.join(d,
                                                         ".writeCommitted"))
                             for d in ranks + serial):
            return (", or its run was a serial one decomposed afterwards "
                    "whose own time folders, which hold the commit markers "
                    "recording its logs, were removed (decomposePar copies "
                    "no marker into processor*/)")
        return ""
    times = []
    for d in glob.glob(os.path.join(case, "*")):
        try:
            float(os.path.basename(d))
        except ValueError:
            continue
        times.append(d)
    if not times or any(os.path.isfile(os.path.join(d, ".writeCommitted"))
                        for d in times):
        return ""
    return (", or its run was a parallel one whose processor*/ folders, "
            "which hold the commit markers recording its logs, were removed "
            "after reconstructPar (reconstructPar does not copy them: keep "
            "processor*/ to measure the run as it wrote it)")


def check(path, handMade=None, option=None):
    """Verify path against its sidecar or the commit markers (see the
    module). handMade: measure it as it is, without a word (the user's
    explicit option, named by option in the messages). Returns the first
    line after the last record (rows not covered), None if none. Without
    handMade and option: the script's (measuring())."""
    if handMade is None:
        handMade = _handMade
    if option is None:
        option = _option
    # no regular file, or beyond a table's size: named first (adv53 l12
    # (f): a FIFO as reference.dat)
    refusal = options.readRefusal(path, options.TABLE_LIMIT, "result file")
    if refusal:
        raise DigestError(refusal)
    if handMade:
        return None
    records = _sidecarRecords(path)
    if records is None:
        records = _markerRecords(path)
    if records is None:
        raise DigestError(
            "%s has no digest of the run that wrote it (no %s beside it, no "
            "commit marker of the case recording it): it was made or "
            "changed by hand, or written before results carried digests%s. "
            "Restore it as the run wrote it, or %s" % (
                path, path + SUFFIX, _reconstructedNote(path),
                _give(option)))
    done = {}
    for n, digest, source, k in records:
        done.setdefault(n, (digest, source, k))
    try:
        st = os.stat(path)
        state = (os.path.abspath(path), st.st_dev, st.st_ino, st.st_size,
                 st.st_mtime_ns, tuple(sorted(done.items())))
    except OSError:
        state = None
    if state is not None and state in _verified:
        return _verified[state]
    # read record by record (adv53 l31 (e): a 1 GiB reference.dat of zeros
    # was read whole, 1.08 GB, before its first line was refused)
    size = os.path.getsize(path)
    h, prev, lines = BASIS, 0, 1     # lines: the line number at byte prev
    with open(path, "rb") as f:
        for n in sorted(done):
            digest, source, k = done[n]
            if n > size:
                f.seek(prev)
                rest = f.read()
                raise DigestError(
                    "%s, line %d: the file ends (%d bytes) before the %d "
                    "bytes its writer recorded (%s, line %d): it was cut "
                    "after it was written. Restore it as the run wrote it, "
                    "or %s" % (path, lines + rest.count(b"\n"), size, n,
                               source, k, _give(option)))
            chunk = f.read(n - prev)
            h = add(h, chunk)
            if h != digest:
                raise DigestError(
                    "%s, line %d: the file is not as the run wrote it (its "
                    "bytes %d to %d, lines %d to %d, differ from the digest "
                    "recorded in %s, line %d): edited or damaged after it "
                    "was written. Restore it as the run wrote it, or %s"
                    % (path, lines, prev + 1, n, lines,
                       lines + chunk.count(b"\n", 0, max(len(chunk) - 1, 0)),
                       source, k, _give(option)))
            lines += chunk.count(b"\n")
            prev = n
    first = lines if prev < size else None
    if state is not None:
        _verified[state] = first
    return first


def checkFinished(case, what):
    """Refuse to measure what (a log of case) while a run goes on in case
    (its lock, caseLock.inUse), unless the script measures a run so far or
    hand-made files: the rows it has so far may all be covered by its
    last write, and a measure of them is a partial run's (adv53 l05:
    plotBlast.py tabled a run at 5-8 ns of 60 without a word)."""
    if _handMade or _partial:
        return
    from . import caseLock
    going = caseLock.inUse(case)
    if going:
        raise DigestError(
            "%s: the case %s is not finished: %s. Its results so far are "
            "partial: wait for the run to end, %sor %s"
            % (what, os.path.realpath(case), going,
               "give %s to measure the run so far, " % _partialOption
               if _partialOption else "", _give(_option)))


def uncoveredRows(path, line, rows=None, partial=None, option=None):
    """Refuse the data rows of path from line on (check's answer: the first
    line after the last record of its run) unless the script measures a
    run so far (partial; default: measuringPartial()) or hand-made files
    (measuring()). rows: the line numbers of the rows the reader keeps (a
    segment's rows that a later segment replaces are not measured);
    default: every line from line on that is not empty nor a '#' note (a
    solver's closing summary is written after its last record). A finished
    run's records cover every row it wrote: rows after them were appended
    by hand, or written by a run killed between its write times or still
    going on (adv54 n01, n02: a row appended to peaks.dat or to a probe log
    was measured as the run's; adv53 l05, adv54 n10: a run going on)."""
    if line is None or _handMade:
        return
    if partial is None:
        partial = _partial
    if partial:
        return
    if option is None:
        option = _option
    if rows is None:
        try:
            with open(path, errors="replace") as f:
                text = f.read().split("\n")
        except OSError:
            return
        rows = [k for k, l in enumerate(text, 1)
                if k >= line and l.strip() and not l.startswith("#")
                and k < len(text)]
    first = next((k for k in rows if k >= line), None)
    if first is None:
        return
    case, rel = _caseOf(path)
    from . import caseLock
    going = caseLock.inUse(case if case is not None
                           else os.path.dirname(os.path.abspath(path)))
    why = ("the run goes on: %s; its results so far are partial. Wait for "
           "the run to end" % going if going else
           "rows appended after the run wrote the file, or written after "
           "its last write time by a run that was stopped there (a "
           "restart computes them again). Restart the run to complete "
           "them, or restore the file as the run wrote it")
    raise DigestError(
        "%s, line %d: the rows from this line on are not covered by the "
        "digests of the run that wrote the file (its last record ends "
        "before it): %s, %sor %s" % (
            path, first, why,
            "give %s to measure a run so far, " % _partialOption
            if _partialOption and not os.path.isfile(path + SUFFIX) else "",
            _give(option)))

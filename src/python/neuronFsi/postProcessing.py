"""Column files of our solvers: postProcessing/<name>/<startTime>/<file>.

Every file starts with '#' header lines, one of which names the columns
with their units ("# time [s]  dt [s]  iterations ..." or "# time [s]
p0[Pa] vonMises0[Pa] ..."; a description may come before it, notes after
it); then one row per time step ('#' lines after the rows, such as
cellBlastFoam's closing summary, are notes). A run
that is continued writes a new segment under its own start time; series()
joins the segments in time order, a later segment replacing the rows of an
earlier one from its first row on (the rows a stopped run wrote after its
last write are computed again by the continued run).

A run that was stopped may leave a last row cut in the middle: it is
dropped. Any other malformed row is an error naming the file and line.
"""

import glob
import math
import os
import re

import numpy as np

from . import options
from . import resultDigest


class ColumnFileError(Exception):
    """A column file that cannot be read; the message names the file."""


# a column name (up to blanks, '[' or '('), a component list "(x y z)" or a
# unit "[Pa]"; two or more blanks separate groups of columns
_HEADER_TOKEN = re.compile(r"\s{2,}|\s|\([^)]*\)|\[[^\]]*\]|[^\s\[(]+")


def columnNames(line):
    """(names, units) of a header line such as "# time [s]  dt [s]
    interfaceForce (x y z) [N]  rho rhoExact [kg/m^3]  p0[Pa] vonMises0[Pa]".
    A component list expands the name before it into name_x, name_y,
    name_z. A unit glued to a name is that name's; after a blank it holds
    for the names before it back to the previous unit or group (two or
    more blanks). Units are '' where the header gives none."""
    names, units = [], []
    first = 0           # first column the next separate unit applies to
    glued = False       # the previous token was a name, no blank between
    for tok in _HEADER_TOKEN.findall(line.lstrip("#")):
        if tok.isspace():
            if len(tok) > 1:
                first = len(names)
            glued = False
            continue
        if tok[0] in "[(" and not names:
            raise ColumnFileError("'%s' before any column name in '%s'"
                                  % (tok, line))
        if tok.startswith("["):
            for k in range(len(names) - 1 if glued else first, len(names)):
                units[k] = tok[1:-1]
            first = len(names)
        elif tok.startswith("("):
            base = names.pop()
            units.pop()
            for c in tok[1:-1].split():
                names.append(base + "_" + c)
                units.append("")
        else:
            names.append(tok)
            units.append("")
        glued = not tok.startswith("[")
    return names, units


class Table:
    """The header and rows of one column file.

    header  the '#' lines before the rows, without the leading '# '
    notes   the '#' lines after the first row (e.g. a closing summary)
    names, units  the columns named by the header (the first line with as
            many names as a row has columns; without rows, the last line)
    rows    the rows as lists of strings
    """

    def __init__(self, path, header, rows, lineNo=None):
        self.path = path
        self.header = header
        self.rows = rows
        # the file's line of each row (1-based), for messages
        self.lineNo = lineNo if lineNo is not None \
            else list(range(1, len(rows) + 1))
        self.names, self.units = [], []
        # the names line: the first with as many names as a row has
        # columns (a description may come before it, notes after it)
        for line in header:
            try:
                names, units = columnNames(line)
            except ColumnFileError:
                continue
            if rows and len(names) == len(rows[0]) or not rows:
                self.names, self.units = names, units
                if rows:
                    break

    def data(self):
        """The rows as a float array (every column must be a number)."""
        if not self.rows:
            return np.empty((0, len(self.names)))
        try:
            return np.array(self.rows, dtype=float).reshape(
                len(self.rows), -1)
        except ValueError as err:
            raise ColumnFileError(_notANumber(self, err))

    def column(self, name, finite=False, increasing=False):
        """One column by its header name: floats, or strings for a column
        of words (e.g. the stage of force.dat). finite: every value a
        finite number; increasing: each above the one before (a time
        column); else a ColumnFileError naming the file and line (adv32
        pl01, pl02: nan forces and times going back were plotted)."""
        col = self._column(name)
        if not (finite or increasing):
            return col
        if not isinstance(col, np.ndarray):
            k = next(k for k, v in enumerate(col)
                     if not _isNumber(v))
            raise ColumnFileError("%s, line %d: column '%s' is '%s', not a "
                                  "number" % (self.path, self.lineNo[k],
                                              name, col[k]))
        bad = np.flatnonzero(~np.isfinite(col))
        if bad.size:
            k = bad[0]
            raise ColumnFileError("%s, line %d: column '%s' is %s, not a "
                                  "finite number" % (self.path,
                                                     self.lineNo[k], name,
                                                     self.rows[k][
                                                         self.names.index(
                                                             name)]))
        if increasing:
            back = np.flatnonzero(np.diff(col) <= 0)
            if back.size:
                k = back[0] + 1
                raise ColumnFileError(
                    "%s, line %d: column '%s' = %.10g is not after the "
                    "previous row's %.10g (line %d): it must increase"
                    % (self.path, self.lineNo[k], name, col[k], col[k - 1],
                       self.lineNo[k - 1]))
        return col

    def _column(self, name):
        if not self.names:
            raise ColumnFileError("%s: no column '%s': the file has no "
                                  "header line ('# name ...'; an empty "
                                  "or cut file?)" % (self.path, name))
        if name not in self.names:
            raise ColumnFileError("%s: no column '%s' (columns: %s)"
                                  % (self.path, name, " ".join(self.names)))
        k = self.names.index(name)
        col = [r[k] for r in self.rows]
        try:
            return np.array(col, dtype=float)
        except ValueError:
            return col


def _isNumber(text):
    try:
        float(text)
        return True
    except ValueError:
        return False


def _lines(path):
    """The lines of a file; a ColumnFileError naming it when it cannot be
    read, or when it is no regular file or beyond a table's size (a FIFO,
    /dev/zero: read without end; options.readRefusal)."""
    refusal = options.readRefusal(path, options.TABLE_LIMIT, "column table")
    if refusal:
        raise ColumnFileError(refusal)
    try:
        with open(path) as f:
            return f.read().split("\n")
    except OSError as err:
        raise ColumnFileError("%s: %s" % (path, err.strerror))


def _notANumber(table, err):
    """The message of table's first field that is not a number, named by
    file, line and column (adv33 sh25: "not a number (could not convert
    ...)", raised uncaught by the plot scripts)."""
    lines = getattr(table, "lineNo", None) or range(1, len(table.rows) + 1)
    for row, line in zip(table.rows, lines):
        for k, value in enumerate(row):
            try:
                float(value)
            except ValueError:
                name = " ('%s')" % table.names[k] \
                    if k < len(table.names) else ""
                return ("%s, line %d, column %d%s: %s is not a number%s"
                        % (table.path, line, k + 1, name,
                           repr(value).replace("\\x00", "\\0"),
                           "; it holds zero bytes (a damaged file)"
                           if "\x00" in value else ""))
    return "%s: not a number (%s)" % (table.path, err)


def readTable(path, vectors=False):
    """Table of one column file; a cut last row (fewer fields than the
    first row, or no newline at its end) is dropped. vectors: the rows hold
    vectors "(x y z)" (an OpenFOAM probes file of a vector field), read as
    their components, one column each."""
    lines = _lines(path)
    header, notes, rows, lineNo = [], [], [], []
    last = len(lines) - 1       # "" after a final newline, else a cut line
    for i, line in enumerate(lines):
        if line.startswith("#"):
            (notes if rows else header).append(line[1:].strip())
        elif line.strip() and i < last:
            if vectors:
                line = line.replace("(", " ").replace(")", " ")
            rows.append(line.split())
            lineNo.append(i + 1)
    n = len(rows[0]) if rows else 0
    # the line of a cut last row dropped (None: none): a file still
    # written; a caller reading a finished file refuses it (table.cut)
    cut = None
    if rows and len(rows[-1]) != n:
        rows.pop()
        cut = lineNo.pop()
    elif last >= 0 and lines[last].strip() and not lines[last].startswith("#"):
        cut = last + 1
    for r, i in zip(rows, lineNo):
        if len(r) != n:
            damaged = "; it holds zero bytes (a damaged file)" \
                if "\x00" in lines[i - 1] else ""
            raise ColumnFileError("%s, line %d: %d columns, the first row "
                                  "has %d%s" % (path, i, len(r), n, damaged))
    table = Table(path, header, rows, lineNo)
    table.notes = notes
    table.lineNo = lineNo
    table.cut = cut
    return table


def segments(case, log):
    """[(startTime, path)] of postProcessing/<dir>/<start>/<file> for log
    "dir/file", earliest start first; an error when there is none."""
    d, name = os.path.split(log)
    found = []
    for p in glob.glob(os.path.join(case, "postProcessing", d, "*", name)):
        try:
            found.append((float(os.path.basename(os.path.dirname(p))), p))
        except ValueError:
            pass
    if not found:
        raise ColumnFileError("no %s" % os.path.join(
            case, "postProcessing", d, "<startTime>", name))
    found.sort()
    sameHeader([_headerOnly(p) for t0, p in found])
    return found


def series(case, log, vectors=False, verify=True):
    """Float rows of log "dir/file" (e.g. "fsi/coupling.dat") over every
    start of the run: each segment's rows before the first row of the next
    segment that has rows, then that segment's rows. The rows delimit the
    segments, not the directory names: these are rounded to the
    controlDict's timePrecision. vectors: see readTable (e.g. "probes/U":
    time, then x y z of each probe). verify (by default: every measure of
    a run reads its logs here): each segment is checked against the
    digests its run recorded (resultDigest.check: a measure of the run
    refuses an edited log, adv52 p06b), and a row kept from it that no
    record covers (appended by hand, or written by a run still going on
    or stopped between its write times) is refused unless the script
    measures a run so far or hand-made files (resultDigest.uncoveredRows:
    adv54 n02, adv53 l05). verify=False: the file's own readers' tests
    only."""
    if verify:
        resultDigest.checkFinished(case, os.path.join("postProcessing", log))
    segs = []
    for t0, p in segments(case, log):
        uncovered = resultDigest.check(p) if verify else None
        table = readTable(p, vectors)
        a = table.data()
        _timesForward(table, a)
        segs.append((p, table, a, uncovered))
    segs = [x for x in segs if len(x[2])]
    if not segs:
        raise ColumnFileError("%s: no rows in %s" % (case, log))
    out = []
    for k, (p, table, a, uncovered) in enumerate(segs):
        keep = a[:, 0] < segs[k + 1][2][0, 0] if k + 1 < len(segs) \
            else np.ones(len(a), dtype=bool)
        if uncovered is not None:
            resultDigest.uncoveredRows(
                p, uncovered,
                [n for n, kept in zip(table.lineNo, keep) if kept])
        out.append(a[keep])
    return np.vstack(out)


def _timesForward(table, a):
    """The first column of a (table's rows as floats), a time, finite and
    never going back within the file: else a ColumnFileError naming the
    file and line (as Table.column's checks; equal times are let through:
    a time printed with few digits repeats)."""
    if not len(a):
        return
    t = a[:, 0]
    bad = np.flatnonzero(~np.isfinite(t))
    if bad.size:
        k = bad[0]
        raise ColumnFileError("%s, line %d: the time (first column) is %s, "
                              "not a finite number" % (
                                  table.path, table.lineNo[k],
                                  table.rows[k][0]))
    back = np.flatnonzero(np.diff(t) < 0)
    if back.size:
        k = back[0] + 1
        raise ColumnFileError("%s, line %d: the time (first column) %.10g "
                              "is before the previous row's %.10g (line %d)"
                              % (table.path, table.lineNo[k], t[k],
                                 t[k - 1], table.lineNo[k - 1]))


def latest(case, log):
    """Table of the latest segment of a log: the output of a utility run on
    the latest time (e.g. "riemannError/errors.dat")."""
    return readTable(segments(case, log)[-1][1])


def header(case, log):
    """The header lines (without '# ') of the first segment of a log."""
    return readTable(segments(case, log)[0][1]).header


def materials(path):
    """The materials a solver built, from its materials.dat (a row per
    region: region, rho0 [kg/m^3], C10 [Pa], d0 [1/Pa], then muN [Pa] and
    tauN [s] per Maxwell branch, as many as the region has; 17 digits):
    region -> {C10, d0, mu1, tau1, ...}."""
    lines = _lines(path)
    mats = {}
    for line in lines:
        if line.startswith("#") or not line.strip():
            continue
        s = line.split()
        if len(s) < 4 or len(s) % 2:
            raise ColumnFileError("%s: malformed line '%s'"
                                  % (path, line.strip()))
        e = {"C10": float(s[2]), "d0": float(s[3])}
        for n in range(1, (len(s) - 4)//2 + 1):
            e["mu%d" % n] = float(s[2 + 2*n])
            e["tau%d" % n] = float(s[3 + 2*n])
        mats[s[0]] = e
    if not mats:
        raise ColumnFileError("%s: no material" % path)
    return mats


def probes(case, log="solidProbes/solidProbes.dat"):
    """The probes the header of the solid probes file names, in order:
    each a dict of name, point [m] (its reference coordinates, 3
    components), region, element (the one containing the point) and patch
    (the number of elements its value is recovered from, one-sided), and
    radius [m]: a ball probe's (the mean over the region within it), 0 for
    a point; across: for a probe across an interface (its pressure and ln
    J read between the two elements containing the point, one per side)
    a dict of region (the other side's), element (its element containing
    the point) and weights (of the probe's element and of that one), else
    None."""
    out = []
    for line in header(case, log):
        m = re.match(r"probe \d+ (\S+) at \((\S+) (\S+) (\S+)\) m in (\w+): "
                     r"element (\d+), patch of (\d+) elements"
                     r"(?:; pressure and ln J across the interface with "
                     r"(\w+): element (\d+), weights (\S+) (\S+))?"
                     r"(?:: the mean over the region within radius (\S+) m)?",
                     line)
        if m:
            across = None if m.group(8) is None else dict(
                region=m.group(8), element=int(m.group(9)),
                weights=(float(m.group(10)), float(m.group(11))))
            out.append(dict(name=m.group(1),
                            point=np.array([float(m.group(k))
                                            for k in (2, 3, 4)]),
                            region=m.group(5), element=int(m.group(6)),
                            patch=int(m.group(7)),
                            radius=float(m.group(12) or 0),
                            across=across))
    return out


def names(case, log):
    """The column names of a log (from its first segment with rows)."""
    tables = [readTable(p) for t0, p in segments(case, log)]
    return next((t for t in tables if t.rows), tables[0]).names


def _headerOnly(path):
    """A Table of a file's header lines only (the '#' lines before its
    first row), for sameHeader."""
    header = []
    for line in _lines(path):
        if not line.startswith("#"):
            if line.strip():
                break
            continue
        header.append(line[1:].strip())
    return Table(path, header, [])


def sameHeader(tables):
    """A ColumnFileError naming both files and the first line where they
    differ unless every table (segment of one log) has the first one's
    header: a run continued with other settings (a probe moved in
    controlDict, adv33 b14, b08) writes another header, and its rows are
    not the same series (they were joined under the first header's
    locations)."""
    first = next((t for t in tables if t.header), None)
    for t in tables:
        if not t.header or t.header == first.header:
            continue
        k = next((k for k, (a, b) in enumerate(zip(first.header, t.header))
                  if a != b), min(len(first.header), len(t.header)))
        line = lambda h: "'# %s'" % h[k] if k < len(h) else "no line"
        raise ColumnFileError(
            "%s and %s: the headers differ at header line %d: %s in the "
            "first, %s in the later one: the run was continued with other "
            "settings (e.g. a probe moved in system/controlDict), its "
            "segments are not one series and were not joined. Compare "
            "them separately, or run again from the start"
            % (first.path, t.path, k + 1, line(first.header),
               line(t.header)))


def latestCommittedTime(case):
    """The latest time [s] the solver wrote and committed in case (a time
    directory with the write guard's .writeCommitted marker, in the case
    or in processor0 for a parallel run), and its directory; (None, None)
    if there is none."""
    best = (None, None)
    for d in glob.glob(os.path.join(case, "*", ".writeCommitted")) + \
            glob.glob(os.path.join(case, "processor0", "*",
                                   ".writeCommitted")):
        d = os.path.dirname(d)
        try:
            t = float(os.path.basename(d))
        except ValueError:
            continue
        if best[0] is None or t > best[0]:
            best = (t, d)
    return best


def lastStep(timeDir):
    """The time step [s] that ended at a time directory the solver wrote
    (deltaT of its uniform/time, written with the time), or None if it
    cannot be read."""
    try:
        with open(os.path.join(timeDir, "uniform", "time")) as f:
            text = f.read()
    except OSError:
        return None
    m = re.search(r"^\s*deltaT\s+([^;\s]+)\s*;", text, re.M)
    try:
        dt = float(m.group(1)) if m else None
    except ValueError:
        return None
    return dt if dt is not None and math.isfinite(dt) and dt > 0 else None


def _lastSegment(case, log):
    """The path of the latest segment of log "dir/file" (postProcessing/
    dir/file if it has none)."""
    try:
        return segments(case, log)[-1][1]
    except ColumnFileError:
        return os.path.join(case, "postProcessing", log)


def checkCovers(case, log, data, afterStep=False):
    """A ColumnFileError unless the rows data of the log "dir/file" reach
    the latest committed time of the case: a cut file was taken as the
    whole run (adv33 pb07: interface maxima of 'the whole run' from half
    the file, exit 0). Our solver's logs are flushed at every step, and
    before each write time is committed. afterStep: a file of OpenFOAM's
    function objects (probes): they run after the time step they follow,
    at the start of the next one, so a run killed after its last write
    has them one step short of that time: the rows must reach the latest
    committed time less its last time step (deltaT of its uniform/time;
    adv34 n14: a probes file cut at 2/3, an impulse 11 % wrong, exit 0)."""
    t, d = latestCommittedTime(case)
    if t is None:
        return
    last = data[-1, 0] if len(data) else None
    # the time's name is the time rounded to timePrecision digits (6 by
    # default, more where OpenFOAM needed them; trailing zeros dropped):
    # the last row, rounded the same way, must reach it (smoke run: the
    # row 2.200335068e-08 s, the time 2.2003351e-08)
    mantissa = os.path.basename(d).lower().split("e")[0].lstrip("+-")
    digits = max(6, len(mantissa.replace(".", "").lstrip("0")))
    step = lastStep(d) if afterStep else None
    if afterStep and step is None:
        raise ColumnFileError(
            "%s: the time step that ended at the latest time the run "
            "wrote, %.10g s, cannot be read (entry deltaT of %s): the "
            "probes file cannot be checked against the run"
            % (_lastSegment(case, log), t,
               os.path.join(d, "uniform", "time")))
    expected = t - step if step else t
    # the rounding of the printed times: a relative 10^-digits
    tol = abs(t)*10.0**(1 - digits)
    if last is None or (float("%.*g" % (digits, last)) < t if not step
                        else last < expected - tol):
        raise ColumnFileError(
            "%s: its rows end at %s, before the latest time the run wrote, "
            "%.10g s (%s)%s: the file is cut (or was replaced by an older "
            "one), it does not cover the run"
            % (_lastSegment(case, log),
               "t = %.10g s" % last if last is not None else "no row", t, d,
               " less its last time step (%.10g s; the probes run after "
               "the step they follow): %.10g s expected" % (step, expected)
               if step else ""))

#!/usr/bin/python3
"""
Application
    sweepCase

Description
    Runs a case once per value of one dictionary entry and tabulates chosen
    outputs: a parameter sensitivity or a study such as the paper's
    pulse-duration study. Each value runs in a copy of the case placed next
    to it (so that the relative paths of its Allrun still hold), removed
    afterwards unless -keep. Every copy is taken from one copy of the case
    made at the sweep's start (<case>.sweep_<name>_base, removed at the
    end): an edit of the case during the sweep reaches no run, and is
    named in a note at the end (adv37 w112: it reached the later runs
    only, the table's rows from two different cases). The table goes to the terminal and to
    <case>/postProcessing/sweep/<name>.{md,csv}. A report of that name
    that exists already (an earlier sweep's) is kept: the sweep stops
    before running anything (move it away, or choose another -name), as
    it does when a run folder exists. Refused rather than written under
    a new number: the runs cost minutes to hours, and a report beside an
    older one of the same name would leave the reader to guess which is
    which.

Usage
    sweepCase -entry <file>/<key>[/<key>...] -values "<v1> <v2> ..."
              -output <name>=<file>:<row>:<column> [-output ...]
              [-case dir] [-run "<command>"] [-nProcs N] [-name n] [-keep]
              [-maxRuns N]

    -entry   the entry to vary, e.g.
             constant/solidProperties/materials/nucleus/C10 or
             constant/indenterProperties/maxDepthIncrement; it must exist
    -output  a number of an output file of the run (relative to the case):
               <row>    a label in the first column (endB, C1,i), an index
                        (0 = first data row, -1 = last), or max/min (the
                        row where <column> is largest/smallest)
               <column> a header name (the '#' line, units in [] ignored,
                        e.g. force) or a 0-based index
             or <name>=<file>:/<regex>/: the first group of the regex's
             last match (e.g. log.cellIndentationFoam:/CPU time (\\S+) s/)
    -run     command run in each copy (default ./Allrun, else the
             controlDict application)
    -maxRuns the most values (runs) of a sweep (default 1000, pulseStudy's
             maxPoints): each run is a copy of the case, kept until the
             sweep ends, and a whole run of its command

    Example (the load step of the indentation, F_B and the CPU time):
        sweepCase -case tutorials/indentation/averageCell \\
            -entry constant/indenterProperties/maxDepthIncrement \\
            -values "0.2e-6 0.1e-6 0.05e-6" -nProcs 2 \\
            -output "F_B [N]=postProcessing/indentation/peaks.dat:endB:force" \\
            -output "CPU [s]=log.cellIndentationFoam:/CPU time (\\S+) s/"

\\*---------------------------------------------------------------------------*/
"""

import argparse
import math
import filecmp
import os
import re
import shutil
import sys
import time

try:
    from neuronFsi import script
except ImportError:
    sys.exit("sweepCase.py: error: the project's Python package neuronFsi "
             "is not found: source the project's etc/bashrc first")
script.guard()  # an input's error: one line, exit 1 (adv33)
from neuronFsi import caseLock, caseRuns, foamDict, options, postProcessing, \
    signals


class SweepError(Exception):
    pass


def _inTheCase(case, f, entry):
    """f (a path relative to the case), normalised, if it names a file of
    the case itself; a SweepError if it leaves the case: '..' out of it
    (adv44 a13: -entry ../<case>/constant/... was the ORIGINAL case's file
    for every run's copy, edited by each run while the copies ran
    unchanged), or a folder on the way that is a symbolic link (its files
    are outside the case, and every copy's link points to the same
    ones). A link at the file itself is fine: each copy's link is
    replaced by a file holding the swept value (run_one)."""
    norm = os.path.normpath(f)
    if os.path.isabs(norm) or norm == os.pardir or \
            norm.startswith(os.pardir + os.sep):
        raise SweepError(
            "-entry %s: the file %s is outside the case %s: each run sets "
            "the entry in its own copy of the case, and a path leaving the "
            "copy would edit the original's file (or another one) while the"
            " copies run unchanged. Nothing was run: give the path of a "
            "file in the case (e.g. constant/indenterProperties/radius)"
            % (entry, norm, case))
    d = case
    for part in norm.split(os.sep)[:-1]:
        d = os.path.join(d, part)
        if os.path.islink(d):
            raise SweepError(
                "-entry %s: the folder %s is a symbolic link (to %s): the "
                "file is outside the case, the same for every run's copy, "
                "which would edit it while the copies run unchanged. "
                "Nothing was run: replace the link by a copy of the folder"
                % (entry, d, os.readlink(d)))
    return norm


def _overridden(text, path, keys, value, entry):
    """The message of a swept value that the dictionary text of path does
    not carry once read as OpenFOAM reads it (its includes merged: adv44
    a15, a '#sinclude "<dictionary>.allrun"' after the entry, the
    tutorials' pattern for Allrun options, set the entry again and every
    run ran with that value, the table listing two values with one
    result), naming the included files that set it; None if it does."""
    d = foamDict.parse(text, path, os.path.dirname(path) or ".")
    for k in keys:
        d = d.get(k) if isinstance(d, dict) else None
    want = foamDict.parse("v %s;" % value, "-values")["v"]
    if d == want:
        return None
    included, by = [], []
    foamDict.parse(text, path, included=included)
    for directive in included:
        name = directive.split(None, 1)[1].strip('"')
        f = os.path.join(os.path.dirname(path), os.path.expandvars(name))
        if os.path.isfile(f):
            e = foamDict.read(f)
            for k in keys:
                e = e.get(k) if isinstance(e, dict) else None
            if e is not None:
                by.append(f)
    return ("-entry %s: set to %s in %s, the dictionary as read (its "
            "includes merged, as OpenFOAM reads it) gives %s: the entry is "
            "set again by %s, included after it. Every run would run with "
            "that value, the table listing values that were not run. "
            "Remove the entry from %s, or sweep it there"
            % (entry, value, path, d, ", ".join(by) or
               "an include directive (%s)" % ", ".join(included),
               ", ".join(by) or "the included file"))


def split_entry(case, entry):
    """(file, [keys]) of <file>/<key>/...: the longest existing file."""
    parts = entry.strip("/").split("/")
    for n in range(len(parts) - 1, 0, -1):
        f = os.path.join(*parts[:n])
        if os.path.lexists(os.path.join(case, f)):
            f = _inTheCase(case, f, entry)
        kind = options.notARegularFile(os.path.join(case, f))
        if kind and kind != "a directory":
            raise SweepError("-entry %s: %s is %s, not a file" % (
                entry, os.path.join(case, f), kind))
        if os.path.isfile(os.path.join(case, f)):
            keys = parts[n:]
            d = foamDict.read(os.path.join(case, f))
            for k in keys[:-1]:
                if not isinstance(d.get(k), dict):
                    raise SweepError("%s: no sub-dictionary '%s'"
                                     % (os.path.join(case, f), k))
                d = d[k]
            if keys[-1] not in d or isinstance(d[keys[-1]], dict):
                values = [k for k in d if not isinstance(d[k], dict)]
                raise SweepError("%s: no entry '%s'%s (entries: %s)"
                                 % (os.path.join(case, f), "/".join(keys),
                                    foamDict.did_you_mean(keys[-1], values),
                                    ", ".join(d)))
            # An entry that comes from an included file cannot be set in
            # this one: said before anything is copied (adv32 w02: "no
            # sub-dictionary" from the first run's copy, run folders left)
            own, included = foamDict.own_entry(os.path.join(case, f), keys)
            if not own:
                raise SweepError(
                    "-entry %s: the entry '%s' is not written in %s itself:"
                    " it comes from a file it includes (%s). sweepCase sets"
                    " an entry in the text of the file named; write the "
                    "entry into %s (after the include, which it then "
                    "overrides), or sweep a copy of the included file. "
                    "Nothing was run" % (
                        entry, "/".join(keys), os.path.join(case, f),
                        ", ".join(included) or "an include directive",
                        os.path.join(case, f)))
            return f, keys
    raise SweepError("-entry %s: no file of case %s in it" % (entry, case))


class Output:
    def __init__(self, spec):
        if "=" not in spec:
            raise SweepError("-output '%s': expected <name>=<file>:<row>:"
                             "<column> or <name>=<file>:/<regex>/" % spec)
        self.name, rest = spec.split("=", 1)
        # the name heads a column of the .md and .csv tables: a newline, a
        # '|', ',' or '"' broke them (adv pass sw25)
        odd = [c for c in self.name if c in '|,"' or not c.isprintable()]
        if not self.name.strip() or odd:
            raise SweepError("-output %r: the name %r is not a column name "
                             "(not empty; no newline or other control "
                             "character, no '|', ',' or '\"': it heads a "
                             "column of the .md and .csv tables)"
                             % (spec, self.name))
        if any(not c.isprintable() for c in rest.split(":/", 1)[0]):
            raise SweepError("-output %r: the file name holds a control "
                             "character (a newline?)" % spec)
        # the whole rest, newlines included (was: '$' matched before a
        # trailing newline and '.' stopped at one: a regex with a newline
        # was taken as <row>:<column>)
        m = re.match(r"([^:]+):/(.*)/\Z", rest, re.S)
        if m:
            self.file = m.group(1)
            try:
                self.regex = re.compile(m.group(2))
            except re.error as err:
                # was: a traceback (issue 19)
                raise SweepError("-output '%s': the regex /%s/ is not a "
                                 "regular expression: %s"
                                 % (spec, m.group(2), err))
            if self.regex.groups < 1:
                raise SweepError("-output '%s': the regex needs a group "
                                 "(...)" % spec)
            # a regex that matches nothing at all matches everywhere: its
            # group was tabulated empty (adv pass sw25)
            if self.regex.search("") is not None:
                raise SweepError("-output %r: the regex /%s/ matches an "
                                 "empty text: it would match where the file"
                                 " has no number (give its group one "
                                 "character at least, e.g. (\\S+))"
                                 % (spec, self.regex.pattern))
            return
        self.regex = None
        try:
            self.file, self.row, self.column = rest.rsplit(":", 2)
        except ValueError:
            raise SweepError("-output '%s': expected <name>=<file>:<row>:"
                             "<column>" % spec)

    def number(self, text, what, path):
        """text if it is a finite number: an output is a number of the run
        (was: an empty match of a regex, or a word, tabulated silently;
        adv pass sw25)."""
        try:
            ok = math.isfinite(float(text))
        except ValueError:
            ok = False
        if not ok:
            raise SweepError("output '%s': %s in %s is %r, not a number (an "
                             "output is a number of the run)"
                             % (self.name, what, path, text))
        return text

    def value(self, case):
        path = os.path.join(case, self.file)
        if not os.path.isfile(path):
            raise SweepError("output '%s': no file %s" % (self.name, path))
        if self.regex:
            found = self.regex.findall(open(path, errors="replace").read())
            if not found:
                raise SweepError("output '%s': no match of /%s/ in %s"
                                 % (self.name, self.regex.pattern, path))
            last = found[-1]
            return self.number(last[0] if isinstance(last, tuple) else last,
                               "the first group of the last match of /%s/"
                               % self.regex.pattern, path)
        try:
            table = postProcessing.readTable(path)
        except postProcessing.ColumnFileError as err:
            raise SweepError("output '%s': %s" % (self.name, err))
        header, rows = table.names, table.rows
        if not rows:
            raise SweepError("output '%s': no data rows in %s"
                             % (self.name, path))
        n = len(rows[0])
        if self.column.lstrip("-").isdigit():
            col = int(self.column)
            # was: a traceback, IndexError (adv30 sw21)
            if not -n <= col < n:
                raise SweepError("output '%s': column %d is outside the "
                                 "valid range [%d, %d] of %s (%d columns;"
                                 " header: %s)"
                                 % (self.name, col, -n, n - 1, path, n,
                                    ", ".join(header)))
        elif self.column in header:
            col = header.index(self.column)
        else:
            raise SweepError("output '%s': no column '%s' in %s (header: "
                             "%s)" % (self.name, self.column, path,
                                      ", ".join(header)))
        what = "column %s" % self.column
        if self.row in ("max", "min"):
            values = [self.number(r[col], what, path) for r in rows]
            return (max if self.row == "max" else min)(
                values, key=float)
        if self.row.lstrip("-").isdigit():
            i = int(self.row)
            if not -len(rows) <= i < len(rows):
                raise SweepError("output '%s': row %d is outside the valid "
                                 "range [%d, %d] of %s (%d data rows)"
                                 % (self.name, i, -len(rows), len(rows) - 1,
                                    path, len(rows)))
            return self.number(rows[i][col], "row %d, %s" % (i, what), path)
        for r in rows:
            if r[0] == self.row:
                return self.number(r[col], "row %s, %s" % (self.row, what),
                                   path)
        raise SweepError("output '%s': no row '%s' in %s (first column: %s)"
                         % (self.name, self.row, path,
                            ", ".join(r[0] for r in rows[:20])))


def _stamp(path):
    """(modification time in ns, size) of a file, or None if absent."""
    try:
        st = os.stat(path)
    except OSError:
        return None
    return st.st_mtime_ns, st.st_size


def _copyCase(case, copy):
    """copytree of the case without its run lock (which the sweep holds: a
    copy of it would be a lock of another case there); copy does not
    exist (checked in main), copytree never replaces"""
    shutil.copytree(case, copy, symlinks=True,
                    ignore=lambda d, names: [caseLock.FILE]
                    if os.path.samefile(d, case) else [])


def _changedSince(case, base):
    """The files of case (its run lock, logs and postProcessing/sweep aside)
    that differ from, or are not in, its copy base, and those of base no
    longer in case: relative paths, sorted"""
    def files(top):
        found = set()
        for d, dirs, names in os.walk(top):
            rel = os.path.relpath(d, top)
            if rel == os.path.join("postProcessing", "sweep"):
                dirs[:] = []
                continue
            for n in names:
                r = os.path.normpath(os.path.join(rel, n))
                if r != caseLock.FILE and not n.startswith("log."):
                    found.add(r)
        return found
    now, was = files(case), files(base)
    changed = sorted((now ^ was) | {
        r for r in now & was
        if not filecmp.cmp(os.path.join(case, r), os.path.join(base, r),
                           shallow=False)})
    return changed


def run_one(case, copy, f, keys, value, outputs, command):
    # case: the sweep's copy of the case taken at its start (adv37 w112:
    # each value copied the case when its run started, and an edit made
    # during the sweep went into the later runs only)
    _copyCase(case, copy)
    p = os.path.join(copy, f)
    text = foamDict.set_entry(foamDict.fileText(p), keys, value, p)
    # by replacement: a link in the copy (to a file outside the case) is
    # replaced by the file, never written through (adv44 a36: the user's
    # shared dictionary outside the case was edited by every run)
    with script.replacing(p) as out:
        out.write(text)
    # the value as the run reads it (adv44 a15: an include after the
    # entry set it again); checked for every value before the first run
    wrong = _overridden(foamDict.fileText(p), p, keys, value, "/".join(keys))
    if wrong:
        raise SweepError("value %s: %s" % (value, wrong))
    # The output files the copy holds before the run: the case's earlier
    # results (copytree keeps their times)
    before = {o.file: _stamp(os.path.join(copy, o.file)) for o in outputs}
    try:
        wall = caseRuns.runIn(copy, command, "log.sweepCase")
    except caseRuns.RunError as err:
        raise SweepError("value %s: %s" % (value, err))
    values = [o.value(copy) for o in outputs]
    # An output the run did not write is the case's earlier result, the
    # same for every value (adv32 w01: ./Allrun skipped every step of a
    # case run before, its logs being there, and the old peaks.dat was
    # reported for each radius)
    for o in outputs:
        stamp = before[o.file]
        if stamp is not None and _stamp(os.path.join(copy, o.file)) == stamp:
            raise SweepError(
                "value %s: output '%s': %s was not written by the run ('%s'"
                "): it is the file of the case as copied (an earlier run's"
                " result; an Allrun skips the steps whose logs are there), "
                "the same for every value. Clean the case first (./Allclean"
                ") so that each run computes its own" % (
                    value, o.name, os.path.join(case, o.file), command))
    return values, wall


# The most runs of a sweep unless -maxRuns raises it (pulseStudy's
# MAX_POINTS, its maxPoints entry)
MAX_RUNS = 1000


def main():
    ap = argparse.ArgumentParser(prog="sweepCase", description="Run a case "
                                 "over values of one entry and tabulate "
                                 "outputs")
    ap.add_argument("-case", default=".")
    ap.add_argument("-entry", required=True)
    ap.add_argument("-values", required=True)
    ap.add_argument("-output", action="append", required=True)
    ap.add_argument("-run")
    ap.add_argument("-nProcs", type=int, default=1)
    ap.add_argument("-name")
    ap.add_argument("-keep", action="store_true")
    ap.add_argument("-maxRuns", type=int, default=MAX_RUNS)
    a = options.parse(ap)
    lock = None
    base, made_base = None, False
    try:
        if a.nProcs < 1:
            raise SweepError("-nProcs %d is outside the valid range [1, inf)"
                             " (runs at a time)" % a.nProcs)
        if a.maxRuns < 1:
            raise SweepError("-maxRuns %d is outside the valid range [1, "
                             "inf) (the most values of a sweep)" % a.maxRuns)
        case = os.path.abspath(a.case)
        if not os.path.isdir(case):
            raise SweepError("-case %s: no such directory" % case)
        # the case path once, before anything is copied: every run goes in
        # a folder beside it, where OpenFOAM's applications refuse the
        # character (adv45 b05 (b): a space in the path was found by the
        # first run's solver, its run folder left)
        problem = options.casePathProblem(case)
        if problem:
            raise SweepError(problem)
        # the solvers' run lock of the case (neuronFsi.caseLock): its
        # copies are taken from it, its report written into it
        lock = caseLock.held(case, "sweepCase").__enter__()
        f, keys = split_entry(case, a.entry)
        outputs = [Output(s) for s in a.output]
        # one column per name (was: two columns named p; adv30 sw09b)
        names = [o.name for o in outputs]
        for o in outputs:
            if names.count(o.name) > 1:
                raise SweepError("-output: the name '%s' is given %d times;"
                                 " each output names one column of the "
                                 "table" % (o.name, names.count(o.name)))
        values = a.values.split()
        if not values:
            raise SweepError("-values: empty")
        # the runs counted before anything is copied (adv47b f55: 10000
        # values accepted, ~4.4 h of runs, every run's folder kept to the
        # end, ~5 GB), as pulseStudy's maxPoints
        if len(values) > a.maxRuns:
            raise SweepError(
                "-values gives %d values, %d runs of the case (each a copy "
                "of it kept until the sweep ends, and a whole run of its "
                "command), more than -maxRuns %d: give fewer values, or "
                "raise -maxRuns if that many is meant. Nothing was copied "
                "or run" % (len(values), len(values), a.maxRuns))
        # each value one token of the entry, checked before anything runs
        # (adv44 a26: nan, "22e-6;fixed" and "}" ran the values before them
        # and then failed at their own run)
        for v in values:
            if re.fullmatch(r"[+-]?(nan|inf|infinity)", v, re.I):
                raise SweepError(
                    "-values '%s': %s is not a number (OpenFOAM reads it as"
                    " a word): give finite numbers. Nothing was run"
                    % (a.values, v))
            bad = sorted(set(c for c in v if c in ';{}"#\\'))
            if bad:
                raise SweepError(
                    "-values '%s': the value '%s' holds %s: a value is one "
                    "word of the entry (a number or a name), without ; { } "
                    "\" # \\. Nothing was run"
                    % (a.values, v, " ".join("'%s'" % c for c in bad)))
            why = options.valueWordProblem(v)
            if why:
                raise SweepError(
                    "-values '%s': the value '%s' is %s. Nothing was copied"
                    " or run" % (a.values, v, why))
        # every value carried by the dictionary as the runs read it
        # (adv44 a15): checked before anything is copied or run
        p = os.path.join(case, f)
        for v in values:
            wrong = _overridden(foamDict.set_entry(
                foamDict.fileText(p), keys, v, p), p, keys, v, a.entry)
            if wrong:
                raise SweepError(wrong + ". Nothing was run")
        command = a.run
        if not command:
            if os.path.isfile(os.path.join(case, "Allrun")):
                command = "./Allrun"
            else:
                command = str(foamDict.read(os.path.join(
                    case, "system/controlDict"))["application"])
        name = a.name or keys[-1]
        # a plain name: it names the run folders <case>.sweep_<name>_<i>
        # and the report postProcessing/sweep/<name>.{md,csv} (was: -name
        # ../.. wrote the report outside the case; issue 19)
        if (not name or name in (".", "..") or "/" in name
                or os.sep in name or "\0" in name):
            raise SweepError("-name '%s' is not a plain name (it names the"
                             " run folders and postProcessing/sweep/<name>"
                             ".{md,csv}): give a name without '/', not '.' "
                             "or '..'" % name)
        copies = ["%s.sweep_%s_%d" % (case, name, i)
                  for i in range(len(values))]
        # The run folders are made and removed by the sweep: one that is
        # there already holds someone's files (a kept or failed earlier
        # sweep, or the user's), which the sweep used to delete
        for c in copies:
            if os.path.lexists(c):
                raise SweepError(
                    "the run folder %s of value %s exists (kept by an "
                    "earlier sweep, or the user's files): the sweep would "
                    "replace it. Nothing was run: move it away, or choose "
                    "another -name" % (c, values[copies.index(c)]))
        # The report of an earlier sweep of this name is kept: checked
        # before anything runs (and written below only if still absent)
        out = os.path.join(case, "postProcessing/sweep")
        reports = [os.path.join(out, name + e) for e in (".md", ".csv")]
        for r in reports:
            if os.path.lexists(r):
                raise SweepError(
                    "the report %s exists (an earlier sweep's): the sweep "
                    "would replace it. Nothing was run: move it away, or "
                    "choose another -name" % r)
        # The case as it is now, for every value's copy (adv37 w112: the
        # later runs took an edit made during the first)
        base = "%s.sweep_%s_base" % (case, name)
        if os.path.lexists(base):
            raise SweepError(
                "the folder %s exists (an earlier sweep's copy of the case, "
                "or the user's files): the sweep would replace it. Nothing "
                "was run: move it away, or choose another -name" % base)
        made_base = True
        _copyCase(case, base)
        print("sweepCase: %s = %s, %d runs of '%s' (%d at a time)"
              % ("/".join([f] + keys), " ".join(values), len(values),
                 command, a.nProcs), flush=True)

        ends = {}
        inputs = caseRuns.filesUnder(base)

        def job(i):
            res = run_one(base, copies[i], f, keys, values[i], outputs,
                          command)
            ends[copies[i]] = time.time()
            print("    %s = %s: %s (wall %.1f s)" % (name, values[i], ", ".join(
                "%s %s" % (o.name, v) for o, v in zip(outputs, res[0])),
                res[1]), flush=True)
            return res

        results = caseRuns.inParallel(a.nProcs, job, range(len(values)))
        changed = _changedSince(case, base)
        if changed:
            print("sweepCase: note: the case changed during the sweep (%s):"
                  " every value ran with the case as it was at the sweep's "
                  "start" % ", ".join(changed[:10]
                                      + (["..."] if len(changed) > 10
                                         else [])), flush=True)
        if not a.keep:
            for c in copies:
                # a run folder holding a file the run did not write (the
                # user's note saved there to look at a result: adv44 a14)
                # is kept, and named with the files
                theirs = caseRuns.filesNotTheRuns(
                    c, inputs, {os.path.normpath(o.file) for o in outputs},
                    ends.get(c, time.time()))
                if theirs:
                    print("sweepCase: note: kept the run folder %s: it "
                          "holds files that are not the run's (%s); remove"
                          " it once they are saved elsewhere"
                          % (c, ", ".join(theirs[:10] + (
                              ["..."] if len(theirs) > 10 else []))),
                          flush=True)
                else:
                    shutil.rmtree(c, ignore_errors=True)
        cols = [name] + [o.name for o in outputs] + ["wall [s]"]
        rows = [[v] + r + ["%.1f" % w] for v, (r, w) in zip(values, results)]
        md = "| " + " | ".join(cols) + " |\n" + "|---" * len(cols) + "|\n" \
            + "".join("| " + " | ".join(r) + " |\n" for r in rows)
        os.makedirs(out, exist_ok=True)
        # "x": a report made meanwhile (another sweep) is not replaced
        with open(reports[0], "x") as m:
            m.write(md)
        with open(reports[1], "x") as c:
            c.write(",".join('"%s"' % x for x in cols) + "\n")
            c.write("".join(",".join(r) + "\n" for r in rows))
        print("\n" + md + "\nWritten %s.{md,csv}" % os.path.join(out, name))
        return 0
    except (SweepError, foamDict.DictError, caseLock.CaseLockError,
            OSError) as err:
        print("sweepCase: error: %s" % err, file=sys.stderr)
        return 1
    finally:
        if base and os.path.isdir(base) and made_base:
            shutil.rmtree(base, ignore_errors=True)
        if lock is not None:
            lock.__exit__(None, None, None)


if __name__ == "__main__":
    # SIGTERM, SIGHUP, SIGINT end the runs started (signals.call) and exit
    # 128 + the signal (adv28 z3: planeWave's run was left running)
    with signals.stopOn("sweepCase"):
        sys.exit(main())

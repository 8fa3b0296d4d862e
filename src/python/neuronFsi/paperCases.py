"""The runs the paper comparison needs (applications/utilities/paperFigures):
its dictionary (system/paperDict), where each run's results are found,
whether they are current, and running a missing one.

A run is a tutorial (a folder of the project's tutorials with an Allrun)
with Allrun options. Its results are looked for first in the tutorial's
own folder under the tutorials folder given (the main job's results,
tutorials/Allrun), then in the comparison's own copy <case>/
postProcessing/runs/<name>. Results are current when

  - the run finished: the solver's log ends with End and has no FATAL,
    and the result files of its kind are there;
  - it ran with the options asked: the Allrun's record (.allrunOptions)
    holds the same options (numbers compared as numbers); a tutorial whose
    Allrun takes no options has no record and must be asked none;
  - its inputs are the tutorial's now: every file git tracks in the
    project's tutorial folder is in the results folder with the same
    content, and none was modified after the solver's log (an input edited
    after the run).

Otherwise the run is made in the comparison's copy: the tracked files of
the tutorial copied into a fresh folder and ./Allrun <options> run there
(log.Allrun).
"""

import json
import os
import re
import shlex
import shutil
import subprocess

from . import (allrunOptions, caseRuns, foamDict, logs, options, planeWave,
               postProcessing, resultDigest)

DICT = os.path.join("system", "paperDict")
RUNS = os.path.join("postProcessing", "runs")

# name: (kind, what the comparison uses it for)
CASES = {
    "averageCell": ("indentation", "Figs. 2, 4-8, Tables 1-2"),
    "validationCell": ("indentation", "Table 3"),
    "blast5ns": ("blast", "Figs. 7-10 (2D)"),
    "blast10ns": ("blast", "Fig. 10"),
    "blast15ns": ("blast", "Fig. 10"),
    "quarter3D": ("blast", "Figs. 7-9 (3D)"),
}
# The pulse of each blast run [s]: the duration its name says (the paper's
# Fig. 10 pulses; the 3D quarter at the paper's 5 ns). A run of another
# pulse under the name was used silently (issue 19, pa19: a 15 ns run as
# blast10ns): refused in the dictionary's options and in the results
PULSE = {"blast5ns": 5e-9, "blast10ns": 10e-9, "blast15ns": 15e-9,
         "quarter3D": 5e-9}
KEYWORDS = ("cases", "peakWindow")
CASE_KEYWORDS = ("tutorial", "options")
SOLVER = {"indentation": "cellIndentationFoam", "blast": "cellBlastFoam"}
RESULTS = {
    "indentation": ("postProcessing/indentation/peaks.dat",
                    "postProcessing/indentation/force.dat",
                    "postProcessing/indentation/solid.h5",
                    "postProcessing/indentation/materials.dat",
                    "constant/cell.msh"),
    "blast": ("solid/solid.h5", "constant/cell.msh",
              "postProcessing/solidProbes", "postProcessing/solidInterfaces",
              "postProcessing/planeWave/0/reference.dat"),
}


class PaperError(Exception):
    """A dictionary entry, a run or a result that is not usable; the
    message names the file and the entry."""


def _text(x):
    if isinstance(x, str):
        return x
    t = repr(x) if isinstance(x, int) else repr(float(x))
    return t[:-2] if t.endswith(".0") else t


def declaration(tutorial):
    """The option declaration of the tutorial's Allrun
    (allrunOptions.allrunDeclaration; {} for one without options)."""
    try:
        return allrunOptions.allrunDeclaration(tutorial)
    except allrunOptions.OptionError as err:
        raise PaperError(str(err))

def read(case, tutorials):
    """The settings of <case>/system/paperDict, checked: {"cases": {name:
    {"tutorial": folder, "options": [...], "given": {option: value},
    "decl": declaration, "kind": ...}}, "peakWindow": [s]}. tutorials: the
    project's tutorials folder the entries 'tutorial' are relative to."""
    path = os.path.join(case, DICT)
    d = foamDict.read_checked(path, KEYWORDS, KEYWORDS, PaperError)
    w = d["peakWindow"]
    if isinstance(w, bool) or not isinstance(w, (int, float)) or \
            not 0 < w <= 1:
        raise PaperError("%s: entry 'peakWindow' = %s is outside the valid "
                         "range (0, 1] s (the Fig. 10 peaks are taken over "
                         "t <= peakWindow)" % (path, foamDict.format_value(w)))
    cases = d["cases"]
    if not isinstance(cases, dict):
        raise PaperError("%s: entry 'cases' is not a sub-dictionary" % path)
    try:
        foamDict.check_keywords(cases, list(CASES), path + ": cases")
    except foamDict.DictError as err:
        raise PaperError(str(err))
    out = {}
    for name, (kind, use) in CASES.items():
        where = "%s: entry 'cases/%s'" % (path, name)
        if name not in cases:
            raise PaperError("%s: no entry 'cases/%s' (the run of %s)"
                             % (path, name, use))
        c = cases[name]
        if not isinstance(c, dict):
            raise PaperError("%s is not a sub-dictionary" % where)
        try:
            foamDict.check_keywords(c, CASE_KEYWORDS, where)
        except foamDict.DictError as err:
            raise PaperError(str(err))
        for k in CASE_KEYWORDS:
            if k not in c:
                raise PaperError("%s: no entry '%s'" % (where, k))
        if not isinstance(c["tutorial"], str):
            raise PaperError("%s: entry 'cases/%s/tutorial' is not a folder "
                             "name" % (path, name))
        tut = os.path.normpath(os.path.join(tutorials, c["tutorial"]))
        if not os.path.isfile(os.path.join(tut, "Allrun")):
            raise PaperError("%s: entry 'cases/%s/tutorial': %s has no "
                             "Allrun" % (path, name, tut))
        opts = c["options"]
        opts = opts if isinstance(opts, list) else [opts]
        opts = [_text(x) for x in opts]
        decl = declaration(tut)
        try:
            given = allrunOptions.parse(decl, opts) if opts else {}
        except allrunOptions.OptionError as err:
            raise PaperError("%s: entry 'cases/%s/options': %s"
                             % (path, name, err))
        if name in PULSE and "-pulse" in given \
                and not _samePulse(float(given["-pulse"]), PULSE[name]):
            raise PaperError("%s: entry 'cases/%s/options': -pulse %s s is "
                             "not the pulse of %s, %g s (the duration its "
                             "name says)" % (path, name, given["-pulse"],
                                              name, PULSE[name]))
        out[name] = {"name": name, "kind": kind, "use": use,
                     "tutorial": tut, "relative": c["tutorial"],
                     "options": opts, "given": given, "decl": decl}
    return {"cases": out, "peakWindow": float(w), "dict": path}


def _samePulse(a, b):
    """Two pulse durations [s] equal to the resolution of a pulse table's
    half-amplitude crossings (1e-3 relative)."""
    return abs(a - b) <= 1e-3*b


def _blastResults(run, folder):
    """Why the blast results in folder are not those of run, or None: the
    pulse of the results (0/p's table, planeWave.pulseShape) must be the
    one the run's name says (pa19), and the solid probes must reach the
    run's endTime (system/controlDict; a cut or truncated probe file was
    used as current, pa09)."""
    try:
        amp, T = planeWave.pulseShape(planeWave.appliedPressure(folder))
    except (planeWave.PlaneWaveError, foamDict.DictError, OSError,
            ValueError, IndexError) as err:
        return "its pulse cannot be read (%s)" % err
    want = PULSE.get(run["name"])
    if want is not None and not _samePulse(T, want):
        return ("its pulse lasts %g s (0/p), not the %g s of %s (the "
                "duration its name says)" % (T, want, run["name"]))
    control = os.path.join(folder, "system", "controlDict")
    try:
        end = foamDict.read(control).get("endTime")
    except (foamDict.DictError, OSError) as err:
        return "%s cannot be read (%s)" % (control, err)
    if isinstance(end, bool) or not isinstance(end, (int, float)):
        return None     # no endTime to compare with
    log = "solidProbes/solidProbes.dat"
    try:
        last = postProcessing.series(folder, log)[-1, 0]
        path = postProcessing.segments(folder, log)[-1][1]
    except (postProcessing.ColumnFileError, resultDigest.DigestError) as err:
        # (a run going on, rows after its last write, an edited log: the
        # digests' refusal, fix19k)
        return str(err)
    if last < end*(1 - 1e-3):
        return ("%s ends at %g s, before the run's endTime %g s (system/"
                "controlDict): a cut or truncated file"
                % (os.path.relpath(path, folder), last, end))
    return None


def trackedFiles(tutorial):
    """The files git tracks in the tutorial folder (relative paths)."""
    out = subprocess.run(["git", "-C", tutorial, "ls-files", "-z", "."],
                         capture_output=True, text=True)
    if out.returncode != 0:
        raise PaperError("%s: git ls-files failed (%s): the tutorials must "
                         "be in the project's git working tree"
                         % (tutorial, out.stderr.strip()))
    files = [f for f in out.stdout.split("\0") if f]
    if "Allrun" not in files:
        raise PaperError("%s: git tracks no Allrun there" % tutorial)
    return files


def _same(a, b):
    with open(a, "rb") as f, open(b, "rb") as g:
        return f.read() == g.read()


def why(run, folder):
    """Why the results in folder are not current for run ({name, kind,
    tutorial, given, decl}), or None when they are."""
    if not os.path.isdir(folder):
        return "no folder"
    log = os.path.join(folder, "log." + SOLVER[run["kind"]])
    if not os.path.isfile(log):
        return "no %s" % os.path.basename(log)
    if not logs.completed(log):
        return "%s did not finish (no End, or a FATAL)" % log
    for r in RESULTS[run["kind"]]:
        if not os.path.exists(os.path.join(folder, r)):
            return "no %s" % r
    if run["kind"] == "blast":
        w = _blastResults(run, folder)
        if w is not None:
            return w
    if run["kind"] == "indentation":
        peaks = os.path.join(folder, RESULTS["indentation"][0])
        with open(peaks) as f:
            if not re.search(r"^endE ", f.read(), re.M):
                return "%s has no endE (the protocol did not finish)" % peaks
    record = os.path.join(folder, ".allrunOptions")
    now = allrunOptions.recorded(run["decl"], run["given"])
    if os.path.isfile(record):
        try:
            with open(record) as f:
                before = json.load(f)["options"]
        except (OSError, ValueError, KeyError, TypeError) as err:
            return "%s is not readable (%s)" % (record, err)
        changed = allrunOptions.changedOptions(run["decl"], before, now)
        if changed:
            return "other options: " + "; ".join(changed)
    elif now:
        return "no record of its options (.allrunOptions)"
    stamp = os.path.getmtime(log)
    for f in trackedFiles(run["tutorial"]):
        p = os.path.join(folder, f)
        if not os.path.isfile(p):
            return "no %s (a file of the tutorial)" % f
        if not _same(p, os.path.join(run["tutorial"], f)):
            return "%s differs from the tutorial's" % f
        if os.path.getmtime(p) > stamp:
            return "%s was modified after the run" % f
    return None


def locate(run, case, results):
    """(folder, notes): the first current results of the run (its folder
    under results, the main job's tutorials folder, then the comparison's
    copy), or (None, notes) with why each was not."""
    notes = []
    for folder in (os.path.join(results, run["relative"]),
                   os.path.join(case, RUNS, run["name"])):
        w = why(run, folder)
        if w is None:
            return folder, notes
        notes.append("%s: %s" % (folder, w))
    return None, notes


def clear(run, folder):
    """Make room for the run's fresh copy at folder (postProcessing/runs/
    <name>): a folder of an earlier run of the comparison (its log.Allrun)
    holding only the run's files is removed; one holding other files -
    the user's, or the run's own that cannot be told from them, e.g. the
    plots an interrupted run's Allrun made at its top (adv44 a43: refused
    naming them as the user's) - is moved aside whole, to <name>.
    interrupted (its solver did not finish) or <name>.earlier (1, 2, ...
    when taken; caseRuns.asideName), and said: never removed. A folder
    that is not an earlier run's (no log.Allrun) holding any file is
    refused naming them (adv44 a12: a folder of the user's notes was
    removed). PaperError if it cannot be made room for; the path it was
    moved to, or None."""
    if not os.path.lexists(folder):
        return None
    try:                            # a killed comparison's run
        caseRuns.checkNoEarlierRun(folder)
    except caseRuns.RunError as err:
        raise PaperError("%s: %s" % (run["name"], err))
    log = os.path.join(folder, "log.Allrun")
    if not os.path.isfile(log):
        theirs = sorted(caseRuns.filesUnder(folder))
        if theirs:
            raise PaperError(
                "%s: %s holds files that are not of a run of the comparison"
                " (%s%s): it would be replaced by the run's copy. Nothing "
                "was changed: move them (or the folder) away"
                % (run["name"], folder, ", ".join(theirs[:10]),
                   ", ..." if len(theirs) > 10 else ""))
        shutil.rmtree(folder)
        return None
    # (no time test: log.Allrun's last line comes before the files of its
    # last step)
    theirs = caseRuns.filesNotTheRuns(folder, set(trackedFiles(
        run["tutorial"])))
    if not theirs:
        shutil.rmtree(folder)
        return None
    solverLog = os.path.join(folder, "log." + SOLVER[run["kind"]])
    finished = os.path.isfile(solverLog) and logs.completed(solverLog)
    aside = caseRuns.asideName(folder, "earlier" if finished
                               else "interrupted")
    os.rename(folder, aside)
    print("%s: the folder of %s run of the comparison, %s, holds files "
          "that may not be the run's (%s%s): moved whole to %s (with any "
          "file you put in it). The comparison does not read it again: "
          "remove it when you no longer need it"
          % (run["name"], "an earlier" if finished else "an interrupted",
             folder, ", ".join(theirs[:10]),
             ", ..." if len(theirs) > 10 else "", aside), flush=True)
    return aside


def make(run, case):
    """Run the tutorial with its options in a fresh copy <case>/
    postProcessing/runs/<name>; the folder. PaperError if it fails or its
    results are then not current."""
    folder = os.path.join(case, RUNS, run["name"])
    # only a folder: a symbolic link (to someone's results) or a file there
    # is not the comparison's copy (pa25, pa26: shutil's traceback)
    for p in (os.path.dirname(os.path.dirname(folder)),
              os.path.dirname(folder), folder):
        if os.path.islink(p) and p == folder:
            kind = "a symbolic link (to %s)" % os.path.realpath(p)
        elif os.path.lexists(p) and not os.path.isdir(p):
            kind = options.notARegularFile(p) or "a file"
        else:
            continue
        raise PaperError("%s: %s is %s, not a folder of the comparison's "
                         "runs: move it away (nothing was changed)"
                         % (run["name"], p, kind))
    clear(run, folder)
    os.makedirs(folder)
    for f in trackedFiles(run["tutorial"]):
        dst = os.path.join(folder, f)
        os.makedirs(os.path.dirname(dst), exist_ok=True)
        shutil.copy2(os.path.join(run["tutorial"], f), dst)
    command = "./Allrun " + " ".join(shlex.quote(o) for o in run["options"])
    try:
        caseRuns.runIn(folder, command, "log.Allrun")
    except caseRuns.RunError as err:
        raise PaperError("%s: %s" % (run["name"], err))
    w = why(run, folder)
    if w is not None:
        raise PaperError("%s: after ./Allrun in %s: %s"
                         % (run["name"], folder, w))
    return folder

"""The pulse study's dictionary, points and records (applications/utilities/
pulseStudy; docs/userGuide/pulseStudy.md).

system/pulseStudyDict:

    baseCase        "$FOAM_TUTORIALS/blast/axisymmetricPreview";
    baseOptions     (-h 0.25e-6);       // Allrun options of every point
    overpressure    (10e6 30e6 100e6);  // [Pa]  Allrun -amplitude
    duration        (2e-9 5e-9 10e-9);  // [s]   Allrun -pulse
    sampleInterval  0.5e-9;             // [s]   Allrun -writeInterval
    strainRateWindow 1e-9;              // [s]   a multiple of it
    nProcs          2;                  // points run at a time
    thresholds
    {
        <name>
        {
            indicator   strain;         // damageIndicators.INDICATORS
            value       0.21 [-];       // its unit, that of the indicator
            source      "authors, year, journal: what, where";
        }
    }

read() checks every entry when it is read: unknown or duplicated keywords,
an empty grid, a value twice, a threshold without its unit or source, and
each point's Allrun command line against the base case's own option
declaration (neuronFsi.allrunOptions: a pulse the water's law cannot carry
is refused with the Allrun's range); StudyError names the file and the
entry.

A point's record (points/<label>/result.json) holds the digest of its
inputs (the base case's files after its Allclean, one digest a file, and
the Allrun command line), its point (label, overpressure, duration), the
indicators' series and the digest of all these (recordDigest), verified
on every read; a point with a record whose inputs match is not run
again. A damaged record or another point's is refused, naming the file.
"""

import hashlib
import json
import math
import os
import re

from . import (allrunOptions, damageIndicators, foamDict, options, ranges,
               uncertainty)

DICT = "system/pulseStudyDict"
KEYWORDS = ("baseCase", "baseOptions", "overpressure", "duration",
            "sampleInterval", "strainRateWindow", "nProcs", "thresholds",
            "uncertainty", "maxPoints")
OPTIONAL = ("uncertainty", "maxPoints")
# The most runs of a study (its grid's points and the uncertainty's runs)
# unless its entry maxPoints raises it: each is a whole blast run (a point
# of the 20 um preview about 12 s of CPU; a point of the paper's case
# hours), and a grid of 1000 x 1000 values was accepted and started, about
# 140 days of runs, its memory growing (adv46b d52)
MAX_POINTS = 1000
THRESHOLD_KEYWORDS = ("indicator", "value", "source")
# the options the study sets per point (not in baseOptions)
STUDY_OPTIONS = ("-amplitude", "-pulse", "-writeInterval", "-noPlots",
                 "-noVTK", "-noRun")
_UNIT = re.compile(r"\[(.*)\]\Z")


# The most writes of a point's run: the solvers' default maxWrites
# (src/foamTools/inputChecks.H checkStepCount)
MAX_WRITES = 10000


# The valid range of a threshold of each indicator (its unit): above 0
# for those that are 0 at rest (von Mises, stretch, rate, heating), either
# sign but not 0 for the pressure (compression +, tension -); the upper
# bounds those of the inputs (src/eos/physicalBounds.H: a modulus below
# 1e13 Pa, temperatures below 1e5 K), a strain of 10 (a stretch of 4.6)
THRESHOLD_RANGES = {"pressure": "[-1e13, 1e13]", "vonMises": "(0, 1e13)",
                    "strain": "(0, 10]", "strainRate": "(0, 1e13]",
                    "temperatureRise": "(0, 1e5)"}


class StudyError(Exception):
    pass


def _number(d, key, where, unit):
    """Entry key of d: a finite number above 0 [unit]; its tighter range
    is checked by read. inf, nan, -0 named with that range and the unit
    (adv48a h09: "inf is not a positive number")."""
    v = d[key]
    if isinstance(v, foamDict.BelowReader):
        return v            # refused naming its range by read
    if isinstance(v, bool) or not isinstance(v, (int, float)) \
            or not math.isfinite(v) or not v > 0:
        raise StudyError("%s: entry '%s' = %s is not a number in the valid "
                         "range (0, inf) %s"
                         % (where, key, foamDict.format_value(v), unit))
    return float(v)


def _grid(d, key, where, unit):
    v = d[key]
    if not isinstance(v, list):
        v = [v]
    if not v:
        raise StudyError("%s: entry '%s' is empty: give one value at least "
                         "[%s]" % (where, key, unit))
    out = []
    for x in v:
        if isinstance(x, foamDict.BelowReader):
            out.append(x)   # refused naming its range by read
            continue
        if isinstance(x, bool) or not isinstance(x, (int, float)) \
                or not math.isfinite(x):
            raise StudyError("%s: entry '%s': '%s' is not a number [%s]"
                             % (where, key, foamDict.format_value(x), unit))
        if float(x) in out:
            raise StudyError("%s: entry '%s': the value %g %s is given twice"
                             % (where, key, x, unit))
        out.append(float(x))
    return out


def _threshold(name, t, where):
    w = "%s: thresholds/%s" % (where, name)
    if not isinstance(t, dict):
        raise StudyError("%s: not a sub-dictionary { indicator ...; value "
                         "<number> [<unit>]; source \"...\"; }" % w)
    try:
        foamDict.check_keywords(t, THRESHOLD_KEYWORDS, w)
    except foamDict.DictError as err:
        raise StudyError(str(err))
    for k in THRESHOLD_KEYWORDS:
        if k not in t:
            raise StudyError("%s: no entry '%s'%s" % (w, k, (
                " (no threshold without its citation: authors, year, "
                "journal, the quantity and the test's conditions)"
                if k == "source" else "")))
    ind = t["indicator"]
    if ind not in damageIndicators.INDICATORS:
        raise StudyError("%s: indicator '%s' unknown%s (valid: %s)" % (
            w, ind, foamDict.did_you_mean(str(ind),
                                          damageIndicators.INDICATORS),
            " ".join(damageIndicators.INDICATORS)))
    unit = damageIndicators.UNITS[ind]
    v = t["value"]
    form = "value <number> [%s]" % unit
    if not isinstance(v, list) or len(v) != 2 \
            or not isinstance(v[1], str) or not _UNIT.match(v[1]):
        raise StudyError("%s: value %s has no unit: give it as '%s' (the "
                         "unit of indicator %s)"
                         % (w, foamDict.format_value(v), form, ind))
    x, u = v
    if isinstance(x, bool) or not isinstance(x, (int, float)) \
            or not math.isfinite(x):
        raise StudyError("%s: value %s is not a number: '%s'"
                         % (w, foamDict.format_value(x), form))
    if _UNIT.match(u).group(1) != unit:
        raise StudyError("%s: value %g %s: the unit of indicator %s is [%s] "
                         "(SI)" % (w, x, u, ind, unit))
    # a value the indicator reaches from the start (0 or below for the
    # positive ones: its time above was the whole run) or never (adv pass
    # st36, st42: accepted silently)
    if x not in ranges.Interval(THRESHOLD_RANGES[ind]) or x == 0:
        raise StudyError("%s: value %g %s is outside the valid range %s %s "
                         "of indicator %s%s" % (
                             w, x, u, THRESHOLD_RANGES[ind], u, ind,
                             " (not 0)" if ind == "pressure" else ""))
    if not isinstance(t["source"], str) or len(t["source"].split()) < 3:
        raise StudyError("%s: source '%s' is not a citation (authors, year,"
                         " journal, the quantity, the test's conditions)"
                         % (w, t["source"]))
    return {"name": name, "indicator": ind, "value": float(x), "unit": unit,
            "source": t["source"]}


def allrunDeclaration(base):
    """The option declaration of the base case's Allrun
    (allrunOptions.allrunDeclaration), which must take options."""
    try:
        opts = allrunOptions.allrunDeclaration(base)
    except allrunOptions.OptionError as err:
        raise StudyError(str(err))
    if not opts:
        raise StudyError("%s: no option declaration (allrunOptions ... "
                         "<<'OPTIONS')" % os.path.join(base, "Allrun"))
    return opts


def _text(x):
    """The option text of a value: exact (repr), without a trailing .0"""
    if isinstance(x, str):
        return x
    t = repr(float(x))
    return t[:-2] if t.endswith(".0") else t


def output(dictionary):
    """The study's output folder (relative to the case) for its
    dictionary: postProcessing/pulseStudy for system/pulseStudyDict,
    postProcessing/pulseStudy.<suffix> for pulseStudyDict.<suffix>, else
    postProcessing/<the dictionary's name>."""
    name = os.path.basename(dictionary)
    if name.startswith("pulseStudyDict"):
        name = "pulseStudy" + name[len("pulseStudyDict"):]
    return "postProcessing/" + name


def read(case, dictionary=DICT):
    """The study's settings of <case>/<dictionary> (system/pulseStudyDict),
    checked."""
    path = os.path.join(case, dictionary)
    d = foamDict.read_checked(
        path, KEYWORDS, [k for k in KEYWORDS if k not in OPTIONAL],
        StudyError, belowReader=True)
    # a number OpenFOAM reads as 0: the entries with a range below name it
    # (adv47b f22), any other is refused now
    foamDict.refuseBelowReader(d, StudyError, keep=(
        "overpressure", "duration", "sampleInterval", "strainRateWindow"))
    base = d["baseCase"]
    if not isinstance(base, str):
        raise StudyError("%s: entry 'baseCase' is not a folder name" % path)
    base = os.path.expandvars(base)
    if "$" in base:
        raise StudyError("%s: entry 'baseCase' = \"%s\": a variable is not "
                         "set" % (path, d["baseCase"]))
    base = os.path.normpath(os.path.join(case, base))
    if not os.path.isfile(os.path.join(base, "Allrun")):
        raise StudyError("%s: entry 'baseCase': %s has no Allrun"
                         % (path, base))
    # a blast case's folders, looked at before any point runs (adv pass
    # ps30: a base without 0.orig failed in every point's Allrun)
    for sub, what in (("0.orig", "the initial fields its Allrun copies to "
                       "0"), ("constant", "its dictionaries"),
                      ("system", "its dictionaries")):
        if not os.path.isdir(os.path.join(base, sub)):
            raise StudyError("%s: entry 'baseCase': %s has no folder %s (%s)"
                             ": not a blast case" % (path, base, sub, what))
    s = {"case": case, "dict": path, "base": base}
    s["overpressure"] = _grid(d, "overpressure", path, "Pa")
    s["duration"] = _grid(d, "duration", path, "s")
    s["sampleInterval"] = _number(d, "sampleInterval", path, "s")
    s["window"] = _number(d, "strainRateWindow", path, "s")
    th = d["thresholds"]
    if not isinstance(th, dict):
        raise StudyError("%s: entry 'thresholds' is not a sub-dictionary"
                         % path)
    s["thresholds"] = [_threshold(k, v, path) for k, v in th.items()]
    opts = d["baseOptions"]
    if not isinstance(opts, list):
        opts = [opts]
    s["baseOptions"] = [_text(x) for x in opts]
    for o in s["baseOptions"]:
        if o in STUDY_OPTIONS:
            raise StudyError("%s: entry 'baseOptions': %s is set by the "
                             "study per point (overpressure, duration, "
                             "sampleInterval; -noPlots and -noVTK always)"
                             % (path, o))
    decl = allrunDeclaration(base)
    for k in ("-amplitude", "-pulse", "-writeInterval", "-noVTK"):
        if k not in decl:
            raise StudyError("%s: entry 'baseCase': %s/Allrun has no option"
                             " %s" % (path, base, k))
    # every point's command line, checked as the Allrun will: the entry
    # named with the Allrun's message
    try:
        allrunOptions.parse(decl, s["baseOptions"])
    except allrunOptions.OptionError as err:
        raise StudyError("%s: entry 'baseOptions': %s" % (path, err))
    for key, opt in (("overpressure", "-amplitude"), ("duration", "-pulse"),
                     ("sampleInterval", "-writeInterval")):
        values = s[key] if isinstance(s[key], list) else [s[key]]
        for v in values:
            if isinstance(v, foamDict.BelowReader):
                raise StudyError("%s (option %s of %s/Allrun)" % (
                    v.problem(decl[opt].range, decl[opt].unitText()), opt,
                    base))
            try:
                decl[opt].check(_text(v))
            except allrunOptions.OptionError as err:
                why = "" if opt != "-amplitude" else (
                    " (a pulse outside it the scene cannot carry: tension "
                    "(no cavitation; the water's Mie-Grueneisen law has no"
                    " state below -rho0 C0^2/(4 s)), or a reflection at "
                    "the substrate beyond the membrane's volumetric law: "
                    "the header of %s/Allrun)" % base)
                raise StudyError("%s: entry '%s': %g: %s%s"
                                 % (path, key, v, err, why))
    # the writes of a point's run: its endTime over sampleInterval, at most
    # the solvers' maxWrites (adv pass ps09: sampleInterval 1e-15 s wrote
    # without end); the window a whole number of samples within the run
    # (ps04, pu04: 5e-324 s was a ZeroDivisionError or an OverflowError)
    given = allrunOptions.parse(decl, s["baseOptions"])
    end = float(given["-endTime"]) if "-endTime" in given \
        else _baseEndTime(base, path)
    sample = s["sampleInterval"]
    if not end/MAX_WRITES <= sample <= end:
        raise StudyError(
            "%s: entry 'sampleInterval' = %g s is outside the valid range "
            "[%g, %g] s: a point's run to endTime %g s would write %s times"
            " (at most %d: the solvers' maxWrites, each write a time "
            "directory of the point's case)"
            % (path, sample, end/MAX_WRITES, end, end, "%.3g" % (end/sample)
               if sample < end else "no", MAX_WRITES))
    if isinstance(s["window"], foamDict.BelowReader):
        raise StudyError(s["window"].problem(
            "[%s, %s]" % (repr(sample), repr(end)), " s"))
    if not sample <= s["window"] <= end:
        raise StudyError(
            "%s: entry 'strainRateWindow' = %g s is outside the valid range"
            " [%g, %g] s (from sampleInterval to the run's endTime)"
            % (path, s["window"], sample, end))
    m = s["window"]/sample
    if abs(m - round(m)) > 1e-9*m:
        raise StudyError("%s: entry 'strainRateWindow' = %g s is not a whole"
                         " number of sampleInterval = %g s" % (
                             path, s["window"], sample))
    s["uncertainty"] = None
    if "uncertainty" in d:
        try:
            s["uncertainty"] = uncertainty.read(
                d["uncertainty"], path, base, s, projectDir())
        except uncertainty.UncertaintyError as err:
            raise StudyError(str(err))
    # at most every run of the study at a time: the grid's points and the
    # uncertainty's runs at its pulses (adv29 s15, s16: 1.5 and 1e12 were
    # said to be outside [1, inf), which holds both)
    n = d["nProcs"]
    grid = len(s["overpressure"])*len(s["duration"])
    extra = len(s["uncertainty"]["pulses"])*len(uncertainty.runs(
        s["uncertainty"])) if s["uncertainty"] else 0
    most = grid + extra
    limit = d.get("maxPoints", MAX_POINTS)
    if isinstance(limit, bool) or not isinstance(limit, (int, float)) \
            or not (math.isfinite(limit) and limit == int(limit)
                    and limit >= 1):
        raise StudyError("%s: entry 'maxPoints' = %s is not valid: a whole "
                         "number in [1, inf) (the most runs of the study; "
                         "default %d)" % (path, foamDict.format_value(limit),
                                          MAX_POINTS))
    if most > limit:
        raise StudyError(
            "%s: the study has %d runs (entry 'overpressure': %d values x "
            "entry 'duration': %d values%s), more than entry 'maxPoints' = "
            "%d%s: each is a whole run of the base case. Nothing was run: "
            "give fewer values, or raise maxPoints if the runs are meant"
            % (path, most, len(s["overpressure"]), len(s["duration"]),
               ", and %d runs of the uncertainty" % extra if extra else "",
               int(limit), " (its default)" if "maxPoints" not in d else ""))
    if isinstance(n, bool) or not isinstance(n, (int, float)) \
            or not (math.isfinite(n) and n == int(n) and 1 <= n <= most):
        raise StudyError("%s: entry 'nProcs' = %s is not valid: a whole "
                         "number in [1, %d] (the points run at a time; the "
                         "grid has %d points%s)"
                         % (path, foamDict.format_value(n), most, grid,
                            ", the uncertainty %d runs" % extra
                            if extra else ""))
    s["nProcs"] = int(n)
    return s


def _baseEndTime(base, where):
    """endTime [s] of the base case's system/controlDict (its Allrun's
    default run length)."""
    path = os.path.join(base, "system", "controlDict")
    try:
        end = foamDict.read(path).get("endTime")
    except (foamDict.DictError, OSError) as err:
        raise StudyError("%s: entry 'baseCase': %s" % (where, err))
    if isinstance(end, bool) or not isinstance(end, (int, float)) \
            or not end > 0:
        raise StudyError("%s: entry 'baseCase': %s has no positive endTime "
                         "(%s)" % (where, path, foamDict.format_value(end)))
    return float(end)


def projectDir():
    """The project's folder: $PROJECT_DIR, else the one of this package."""
    return os.environ.get("PROJECT_DIR") or os.path.normpath(os.path.join(
        os.path.dirname(os.path.abspath(__file__)), "..", "..", ".."))


def labelTexts(values):
    """{value: its text in the points' labels}: 6 significant digits (the
    labels of the studies made so far), more where two distinct values of
    the list would read the same (issue 19, adv44 a03: 30e6 and
    30.0000001e6 both gave p3e+07_T2e-09, one folder for two points, the
    first point's record replaced by the second's): the fewest digits, from
    6 to 17, that tell the value apart from every other of the list."""
    distinct = sorted(set(values))
    out = {}
    for v in distinct:
        for n in range(6, 18):
            text = "%.*g" % (n, v)
            if all("%.*g" % (n, w) != text for w in distinct if w != v):
                break
        out[v] = text
    return out


def points(s):
    """The grid's points: dicts of overpressure [Pa], duration [s], label
    (p<overpressure>_T<duration>, labelTexts: unique for distinct values),
    and the Allrun options."""
    out = []
    pText = labelTexts(s["overpressure"])
    tText = labelTexts(s["duration"])
    for A in s["overpressure"]:
        for T in s["duration"]:
            opts = s["baseOptions"] + [
                "-amplitude", _text(A), "-pulse", _text(T),
                "-writeInterval", _text(s["sampleInterval"]),
                "-noPlots", "-noVTK"]
            out.append({"overpressure": A, "duration": T,
                        "label": "p%s_T%s" % (pText[A], tText[T]),
                        "options": opts})
    return out


def uncertaintyPoints(s):
    """The runs the 'uncertainty' sub-dictionary adds: at each of its
    pulses, each variant and each finite-difference run, a point with the
    grid point's options and a material change; label
    <grid point's label>_<run> (uncertainty.runs)."""
    u = s.get("uncertainty")
    if not u:
        return []
    grid = {(p["overpressure"], p["duration"]): p for p in points(s)}
    out = []
    for A, T in u["pulses"]:
        g = grid[(A, T)]
        for name, change in uncertainty.runs(u):
            out.append(dict(g, label="%s_%s" % (g["label"], name),
                            run=name, pulse=g["label"], change=change))
    return out


def fileDigests(folder):
    """{relative path: sha256} of every file under folder."""
    out = {}
    for root, dirs, files in os.walk(folder):
        dirs.sort()
        for f in sorted(files):
            p = os.path.join(root, f)
            with open(p, "rb") as h:
                out[os.path.relpath(p, folder)] = \
                    hashlib.sha256(h.read()).hexdigest()
    return out


# An include directive of OpenFOAM's dictionaries: #include, #sinclude,
# #includeIfPresent, #includeEtc, #includeFunc
_INCLUDE = re.compile(rb"#s?include\w*")
# A 'file' entry (a tableFile's or csvFile's table, the solid's mesh)
_FILE = re.compile(r'(?<![\w.])file\s+(?:"([^"]*)"|([^\s;"]+))\s*;')


def _inside(path, folder):
    path, folder = os.path.realpath(path), os.path.realpath(folder)
    return path == folder or path.startswith(folder + os.sep)


def outsideInputs(case):
    """What the dictionaries of case (the files of its folders, e.g.
    constant/, system/, 0.orig/) read from outside it, resolved as
    OpenFOAM resolves it (adv43 k23: a material set #included from
    outside the base case was changed between two runs of a study, and
    the finished points were kept, the new ones run with the other set):
    {key: sha256}, keys

      "<file> as OpenFOAM reads it (foamDictionary -expand)": each file
          with an include directive (#include, #sinclude, #includeEtc,
          #includeFunc, ...), the dictionary it makes with every include
          expanded, every number with 17 digits (foamDictionary
          -precision 17 -expand; a file it cannot read: its message)
      "<absolute path> (included by <file>)": each file outside case
          the #include and #sinclude directives name (foamDictionary
          -includes), to name the file that changed: as OpenFOAM reads it
          (foamDictionary -precision 17 -expand: a comment, the layout or
          a number's spelling is no change, as in the solvers' record),
          its bytes if it cannot be read alone
      "<absolute path> (entry 'file' of <file>)": the bytes of each file
          outside case a 'file' entry names (a boundary condition's
          tableFile, the solid's mesh), relative paths from case

    A file inside case is a file of the case (its own digest)."""
    import shutil
    import subprocess
    out = {}
    # a #calc or #codeStream compiles its code into <case>/dynamicCode:
    # removed again if this made it (the case's files are its inputs)
    code = os.path.join(case, "dynamicCode")
    hadCode = os.path.lexists(code)

    def foamDictionary(args, rel):
        r = subprocess.run(["foamDictionary", "-case", case] + args + [rel],
                           cwd=case, stdout=subprocess.PIPE,
                           stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL)
        return r.returncode, r.stdout

    def parsed(path):
        """The file as OpenFOAM reads it, a comment or a number's spelling
        not a change (as the solvers' record, foamTools::inputRecord; adv44
        a40); its bytes if it is not a dictionary of its own"""
        rc, text = foamDictionary(["-precision", "17", "-expand"], path)
        if rc == 0:
            return text
        with open(path, "rb") as h:
            return h.read()

    def named(text, rel):
        for m in _FILE.finditer(text):
            name = m.group(1) if m.group(1) is not None else m.group(2)
            for var in ("$FOAM_CASE", "${FOAM_CASE}", "<case>"):
                name = name.replace(var, case)
            name = os.path.expanduser(os.path.expandvars(name))
            path = os.path.normpath(os.path.join(case, name))
            if os.path.isfile(path) and not _inside(path, case):
                with open(path, "rb") as h:
                    out["%s (entry 'file' of %s)" % (path, rel)] = \
                        hashlib.sha256(h.read()).hexdigest()

    for root, dirs, files in os.walk(case):
        dirs.sort()
        if root == case:
            continue        # Allrun, Allclean, README: not dictionaries
        for f in sorted(files):
            full = os.path.join(root, f)
            rel = os.path.relpath(full, case)
            if not os.path.isfile(full):
                continue
            with open(full, "rb") as h:
                data = h.read()
            text = data
            if _INCLUDE.search(data):
                rc, text = foamDictionary(["-precision", "17", "-expand"],
                                          rel)
                out["%s as OpenFOAM reads it (foamDictionary -expand)"
                    % rel] = hashlib.sha256(text).hexdigest()
                if rc == 0:
                    for line in foamDictionary(["-includes"], rel)[1] \
                            .decode(errors="replace").splitlines():
                        path = line.strip().strip('"')
                        if os.path.isabs(path) and os.path.isfile(path) \
                                and not _inside(path, case):
                            out["%s (included by %s)" % (path, rel)] = \
                                hashlib.sha256(parsed(path)).hexdigest()
            named(text.decode("latin-1"), rel)
    if not hadCode and os.path.isdir(code):
        shutil.rmtree(code)
    return out


def inputs(baseDigests, point, outside=None):
    """What a point's results depend on: the base case's files, what they
    read from outside it (outsideInputs) and the Allrun command line."""
    out = {"baseFiles": baseDigests, "options": point["options"]}
    if outside is not None:
        out["outside"] = outside
    if point.get("change"):
        out["materials"] = point["change"]
    return out


def differences(before, now):
    """The entries of the dictionary whose change makes a record's inputs
    differ from now's, with what differs; [] for the same inputs."""
    out = []
    fb, fn = before.get("baseFiles", {}), now["baseFiles"]
    files = sorted(f for f in set(fb) | set(fn) if fb.get(f) != fn.get(f))
    if files:
        out.append(("baseCase", "its files differ from those the point ran "
                    "with: %s" % ", ".join(files[:5])
                    + (" ..." if len(files) > 5 else "")))
    # what the base case reads from outside it: a record of an earlier
    # build holds none (what it ran with is not known: refused as well)
    ob, on = before.get("outside", {}), now.get("outside", {})
    files = sorted((f for f in set(ob) | set(on) if ob.get(f) != on.get(f)),
                   key=lambda f: (not f.startswith("/"), f))
    if files:
        out.append(("baseCase", "what it reads from outside its folder "
                    "differs from what the point ran with: %s" % "; ".join(
                        "%s%s" % (f, " (no longer read)" if f not in on
                                  else "" if f in ob else
                                  " (not in the point's record%s)" % (
                                      "" if "outside" in before else
                                      ": a record of an earlier build"))
                        for f in files[:4])
                    + (" ..." if len(files) > 4 else "")))
    ob, on = before.get("options", []), now["options"]
    if ob != on:
        key = "sampleInterval" if _option(ob, "-writeInterval") != \
            _option(on, "-writeInterval") else "baseOptions"
        out.append((key, "the Allrun options were '%s', now '%s'"
                    % (" ".join(ob), " ".join(on))))
    mb, mn = before.get("materials", {}), now.get("materials", {})
    if mb != mn:
        keys = sorted({(r, e) for m in (mb, mn) for r in m for e in m[r]})
        what = ["%s.%s was %s, now %s" % (r, e, mb.get(r, {}).get(e, "not"
                                                              " changed"),
                                           mn.get(r, {}).get(e, "not "
                                                             "changed"))
                for r, e in keys
                if mb.get(r, {}).get(e) != mn.get(r, {}).get(e)]
        out.append(("uncertainty", "its material change differs: %s"
                    % "; ".join(what)))
    return out


def _option(opts, name):
    return opts[opts.index(name) + 1] if name in opts[:-1] else None


def recordDigest(record):
    """The SHA-256 of a point's record without its own 'digest' entry, as
    JSON with sorted keys: what its 'digest' entry must be (the values
    read back from JSON are the doubles written, so the digest is the same
    on every read)."""
    return hashlib.sha256(json.dumps(
        {k: v for k, v in record.items() if k != "digest"}, sort_keys=True,
        separators=(",", ":"), allow_nan=False).encode()).hexdigest()


def writeRecord(path, record):
    """record as JSON (NaN as null) with the digest of its values
    (recordDigest), atomically."""
    def clean(x):
        if isinstance(x, float) and not math.isfinite(x):
            return None
        if isinstance(x, dict):
            return {k: clean(v) for k, v in x.items()}
        if isinstance(x, (list, tuple)):
            return [clean(v) for v in x]
        return x
    record = clean(record)
    record["digest"] = recordDigest(record)
    tmp = path + ".tmp%d" % os.getpid()
    with open(tmp, "w") as f:
        json.dump(record, f)
        f.write("\n")
    os.replace(tmp, path)


def readRecord(path, point=None):
    """A point's record, verified; None if it has none. A record that is
    not one (not JSON, entries missing), whose values are not those its
    digest was made of (edited or damaged: adv29 sr05, sr05c) or, with
    point, that is another point's (its label, overpressure or duration:
    a record copied or moved, sr07) is a StudyError naming the file:
    nothing runs, and the record is left as it is (the user moves it away
    to run the point again). Records are written atomically: a cut one is
    damaged, not an interrupted write."""
    if not os.path.lexists(path):
        return None
    rerun = ("Nothing was run: move the file away (or remove it) to run "
             "the point again")

    def damaged(why):
        return StudyError("%s: the point's record is damaged (%s): its "
                          "values cannot be used. %s" % (path, why, rerun))
    # a FIFO blocked the study at the open (adv pass ps25): looked at first
    kind = options.notARegularFile(path)
    if kind:
        raise StudyError("%s is %s, not a point's record (a file written by "
                         "pulseStudy). %s" % (path, kind, rerun))
    try:
        with open(path) as f:
            r = json.load(f)
    except (OSError, UnicodeDecodeError) as err:
        raise damaged("cannot be read: %s" % err)
    except ValueError as err:
        raise damaged("not JSON: %s" % err)
    if not isinstance(r, dict):
        raise damaged("not a JSON object")
    missing = [k for k in ("inputs", "series", "digest") if k not in r]
    if missing:
        raise damaged("no entry %s%s" % (", ".join(missing), "; a record "
                      "written before the records carried the digest of "
                      "their values" if missing == ["digest"] else ""))
    try:
        now = recordDigest(r)
    except (TypeError, ValueError) as err:
        raise damaged(str(err))
    if now != r["digest"]:
        raise damaged("the digest of its values is %s, the one it carries "
                      "%s: a value was changed since it was written"
                      % (now, r["digest"]))
    if point is not None:
        theirs = (r.get("label"), r.get("overpressure"), r.get("duration"))
        ours = (point["label"], point["overpressure"], point["duration"])
        if theirs != ours:
            raise StudyError(
                "%s is the record of another point (%s: overpressure %s Pa, "
                "duration %s s), not of %s (overpressure %g Pa, duration %g "
                "s): copied or moved there. Its values are not this point's."
                " Nothing was run: put it back in its own folder, or move it"
                " away to run %s again" % (
                    path, theirs[0], theirs[1], theirs[2], ours[0], ours[1],
                    ours[2], ours[0]))
    return r

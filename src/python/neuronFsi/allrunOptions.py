"""The options of the tutorials' Allrun scripts, parsed and checked in one
place (etc/RunFunctions allrunOptions, allrunCalc; issue 19).

An Allrun declares its options, one a line:

    -option  variable  kind  unit  [noRecord]

kind is one of
    number(lo,hi)   a finite decimal number (no nan, inf, expression) in
                    the interval; brackets as in mathematics: ( ) open,
                    [ ] closed, inf for no bound
    integer[lo,hi]  a whole number in the interval
    choice=a,b      one of the words
    flag=VALUE      takes no value: sets variable to VALUE
    number(...)|none  also the word none
unit is the unit printed with a value ("-" for none). noRecord: the option
does not change the case's results (-noRun, -noPlots) and is not part of
the record of the run. A line

    %results FILE...

names files an earlier run of the Allrun leaves (e.g. log.cellMesh).

parse() checks the command line against the declaration: an unknown
option (with the closest valid one), an option given twice, an option
without its value (last on the line), a value that is not a number of the
option's kind or lies outside its range are errors naming the option, the
value and the valid range. The values are printed as shell assignments
(shell-quoted), for the Allrun to eval; no option's text is ever
evaluated, neither by the shell nor by Python.

main() first checks the case, the Allrun's folder (its working
directory): a path holding a character OpenFOAM's file names drop (a
space, a quote) is refused with the project's message
(options.casePathProblem), before any step runs.

The record (a file of the case, e.g. .allrunOptions): a re-run of the
Allrun over a case that holds an earlier run's results must not silently
keep results computed with other options (runApplication skips every step
whose log exists). With a record, the options now are compared with those
recorded and any change refused, naming the option, its two values and
how to start over (./Allclean); without a record but with one of the
%results files, refused likewise (the earlier options are unknown). A
record without any of the %results files (the earlier run stopped before
its first step) is replaced. Otherwise the record is written (atomically)
and the run goes on.
"""

import json
import math
import os
import re
import shlex
import sys

from . import foamDict, options, ranges

# ASCII digits only: Python's \d (and float()) take any script's digits,
# '\u0661e-\u0669' was accepted and written into controlDict.allrun, where
# the solver refused it naming the file, not the option (adv46b d35)
NUMBER = re.compile(r"[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?\Z", re.ASCII)
INTEGER = re.compile(r"[+-]?\d+\Z", re.ASCII)


class OptionError(Exception):
    pass


class Option:
    """One declared option."""

    def __init__(self, line):
        words = line.split()
        if len(words) < 3:
            raise ValueError("option declaration '%s': expected "
                             "'-option variable kind [unit] [noRecord]'"
                             % line)
        self.name, self.var, kind = words[0], words[1], words[2]
        self.unit = words[3] if len(words) > 3 else "-"
        self.record = "noRecord" not in words[4:]
        if not re.match(r"[A-Za-z_][A-Za-z0-9_]*\Z", self.var):
            raise ValueError("option %s: variable '%s' is not a shell name"
                             % (self.name, self.var))
        self.words = []
        self.flag = None
        self.kind = None
        alternatives = kind.split("|")
        for a in alternatives[1:]:
            self.words.append(a)
        kind = alternatives[0]
        if kind.startswith("flag="):
            self.flag = kind[len("flag="):]
        elif kind.startswith("choice="):
            self.words += kind[len("choice="):].split(",")
        else:
            m = re.match(r"(number|integer)(.*)\Z", kind)
            try:
                self.range = ranges.Interval(m.group(2)) if m else None
            except ValueError:
                self.range = None
            if not self.range:
                raise ValueError("option %s: kind '%s' is not number(lo,hi),"
                                 " integer[lo,hi], choice=..., flag=..."
                                 % (self.name, kind))
            self.kind = m.group(1)
            self.interval = str(self.range)

    def unitText(self):
        return "" if self.unit == "-" else " " + self.unit

    def valid(self):
        """The valid values, in words."""
        parts = []
        if self.kind:
            parts.append("%s in %s%s" % ("a whole number" if
                                          self.kind == "integer" else
                                          "a number", self.interval,
                                          self.unitText()))
        if self.words:
            parts.append(" or ".join(self.words))
        return " or ".join(parts)

    def check(self, text):
        """text, checked; OptionError naming the option otherwise."""
        if text in self.words:
            return text
        if not self.kind:
            raise OptionError(
                "option %s = '%s' is not valid (valid: %s)%s"
                % (self.name, text, self.valid(),
                   foamDict.did_you_mean(text, self.words)))
        pattern = INTEGER if self.kind == "integer" else NUMBER
        if self.kind == "integer" and NUMBER.match(text):
            # a whole number with an exponent or a decimal point (1e3,
            # 2.0) is a number the solvers' readers do not take as an
            # integer: said so, with the range (adv38 x65: "'1e9' is not
            # a whole number")
            x = float(text)
            if not INTEGER.match(text):
                raise OptionError(
                    "option %s = '%s' is written with an exponent or a "
                    "decimal point%s: write the whole number with digits "
                    "only (valid: %s)"
                    % (self.name, text, " (%d)" % x if math.isfinite(x)
                       and x == int(x) and abs(x) < 1e18 else "",
                       self.valid()))
        if not pattern.match(text):
            raise OptionError(
                "option %s = '%s' is not %s (valid: %s)"
                % (self.name, text, "a whole number" if self.kind ==
                   "integer" else "a decimal number", self.valid()))
        x = float(text)
        if not math.isfinite(x):
            raise OptionError(
                "option %s = %s is beyond the range of a number (a double "
                "holds |x| <= 1.79769e+308; valid: %s)"
                % (self.name, text, self.valid()))
        # what OpenFOAM's reader would not take as written (adv33 ar01:
        # -endTime 1e-301 accepted, then planeWave's "-endTime 0 s")
        why = ranges.readerRangeProblem(text, x)
        if why:
            raise OptionError("option %s = %s%s %s (valid: %s)"
                              % (self.name, text, self.unitText(), why,
                                 self.valid()))
        if x not in self.range:
            raise OptionError(
                "option %s = %s%s is outside the valid range %s%s"
                % (self.name, text, self.unitText(), self.interval,
                   self.unitText()))
        return text


def declaration(text):
    """(options by name, %results files) of a declaration."""
    opts = {}
    results = []
    for line in text.splitlines():
        line = line.split("#", 1)[0].strip()
        if not line:
            continue
        if line.startswith("%results"):
            results += line.split()[1:]
            continue
        o = Option(line)
        if o.name in opts:
            raise ValueError("option %s declared twice" % o.name)
        opts[o.name] = o
    return opts, results



def allrunDeclaration(folder):
    """The option declaration of <folder>/Allrun: the options of the text
    between 'allrunOptions ... <<'OPTIONS'' and 'OPTIONS'; {} for an
    Allrun that takes no options ('allrunOptions "" "$@" < /dev/null').
    An unreadable Allrun or one without either form: OptionError naming
    the file."""
    path = os.path.join(folder, "Allrun")
    try:
        with open(path) as f:
            text = f.read()
    except OSError as err:
        raise OptionError("%s: cannot read (%s)" % (path, err.strerror))
    m = re.search(r"allrunOptions [^\n]*<<'OPTIONS'\n(.*?)\nOPTIONS\n", text,
                  re.S)
    if m:
        return declaration(m.group(1))[0]
    if re.search(r"allrunOptions [^\n]*< */dev/null", text):
        return {}
    raise OptionError("%s: no option declaration (allrunOptions ... "
                      "<<'OPTIONS')" % path)

def parse(opts, argv):
    """{option: value text} of the command line argv (flags: their
    VALUE)."""
    given = {}
    i = 0
    while i < len(argv):
        a = argv[i]
        o = opts.get(a)
        if not opts:
            raise OptionError("takes no options (given: %s)"
                              % " ".join(shlex.quote(x) for x in argv))
        if o is None:
            raise OptionError(
                "unknown option '%s'%s (valid: %s; see the header of Allrun)"
                % (a, foamDict.did_you_mean(a, list(opts)), " ".join(opts)))
        if o.flag is not None:
            value = o.flag
            i += 1
        else:
            if i + 1 >= len(argv):
                raise OptionError("option %s needs a value (valid: %s)"
                                  % (a, o.valid()))
            value = o.check(argv[i + 1])
            i += 2
        if a in given:
            raise OptionError("option %s given twice (%s and %s): give it "
                              "once" % (a, given[a], value))
        given[a] = value
    return given


def _same(o, a, b):
    if a == b:
        return True
    if o is not None and o.kind and a not in o.words and b not in o.words:
        try:
            return float(a) == float(b)
        except (TypeError, ValueError):
            return False
    return False


def recorded(opts, given):
    """The options of given that change the results (those a record
    keeps)."""
    return {k: v for k, v in given.items() if opts[k].record}


def changedOptions(opts, before, now):
    """["<option> <value> then, <value> now"] for the recorded options
    that differ between two {option: value text} (numbers compared as
    numbers); [] for the same options."""
    changed = []
    for k in sorted(set(before) | set(now), key=lambda k: (
            list(opts).index(k) if k in opts else len(opts), k)):
        b, n = before.get(k), now.get(k)
        if not _same(opts.get(k), b, n):
            changed.append("%s %s then, %s now" % (
                k, b if b is not None else "not given (default)",
                n if n is not None else "not given (default)"))
    return changed


def checkRecord(opts, given, record, results, prog="Allrun"):
    """Refuse a re-run over an earlier run's results with other options;
    else write the record (the options that change the results)."""
    now = recorded(opts, given)
    start = ("start over with ./Allclean (it removes the earlier results) "
             "or in a fresh copy of the case, or re-run with the earlier "
             "options")
    found = [f for f in results if os.path.lexists(f)]
    if os.path.exists(record) and found:
        try:
            with open(record) as f:
                before = json.load(f)["options"]
            if not isinstance(before, dict):
                raise ValueError("no options")
        except (OSError, ValueError, KeyError, TypeError) as e:
            raise OptionError(
                "%s: the record of the earlier run's options is not "
                "readable (%s): %s" % (record, e, start))
        changed = changedOptions(opts, before, now)
        if changed:
            raise OptionError(
                "this case holds the results of an earlier ./%s with "
                "other options (%s): %s. A re-run keeps every step already "
                "done (runApplication skips a step whose log exists), so "
                "its results would not be those of the new options: %s"
                % (prog, record, "; ".join(changed), start))
        return
    if found and not os.path.exists(record):
        raise OptionError(
            "this case holds results of an earlier run (%s) whose options "
            "were not recorded (%s is missing): they may not be those of "
            "this run's options: %s" % (", ".join(found), record, start))
    tmp = record + ".tmp%d" % os.getpid()
    try:
        with open(tmp, "w") as f:
            json.dump({"program": prog, "options": now}, f, indent=1)
            f.write("\n")
        os.replace(tmp, record)
    except OSError as e:
        try:
            os.unlink(tmp)
        except OSError:
            pass
        raise OptionError("cannot write the record of the options %s: %s"
                          % (record, e.strerror or e))


def assignments(opts, given):
    """The shell assignments of the given options."""
    return "".join("%s=%s\n" % (opts[k].var, shlex.quote(v))
                   for k, v in given.items())


def calc(expr, values):
    """The value of the Allrun's own expression expr (not user text) with
    the names of values bound to floats (each value checked a number)."""
    env = {}
    for nv in values:
        name, _, text = nv.partition("=")
        t = text.strip()
        if not NUMBER.match(t) or not math.isfinite(float(t)):
            raise OptionError("%s = '%s' is not a finite decimal number"
                              % (name, text))
        env[name] = float(t)
    r = eval(expr, {"__builtins__": {}, "max": max, "min": min,
                    "round": round}, env)
    return r


def main(argv):
    """allrunOptions PROG RECORD -- ARGS... (declaration on stdin), or
    --calc EXPR NAME=VALUE..."""
    try:
        if argv[:1] == ["--calc"]:
            print(calc(argv[1], argv[2:]))
            return 0
        prog, record = argv[0], argv[1]
        args = argv[3:] if argv[2:3] == ["--"] else argv[2:]
        # the case (the Allrun's folder, its working directory) once, up
        # front: OpenFOAM cannot run in a path holding a space (adv29 z4:
        # foamDictionary's "stripInvalid", then an unrelated error)
        problem = options.casePathProblem(os.getcwd(),
                                          " (the Allrun's folder)")
        # and as the shell reached it ($PWD, through symbolic links),
        # which OpenFOAM's applications take (adv38 x08)
        logical = os.environ.get("PWD", "")
        if not problem and os.path.isabs(logical) \
                and os.path.realpath(logical) == os.path.realpath(os.getcwd()):
            problem = options.casePathProblem(
                logical, " (the Allrun's folder as the shell reached it, "
                "$PWD, through a symbolic link: OpenFOAM's applications "
                "take that path)", logical=True)
        if problem:
            raise OptionError(problem)
        try:
            opts, results = declaration(sys.stdin.read())
        except ValueError as e:
            print("%s: internal error in the option declaration: %s"
                  % (prog, e), file=sys.stderr)
            return 2
        given = parse(opts, args)
        if record:
            checkRecord(opts, given, record, results, prog)
        sys.stdout.write(assignments(opts, given))
        return 0
    except OptionError as e:
        print("%s: error: %s" % (argv[0] if argv[:1] != ["--calc"]
                                 else "Allrun", e), file=sys.stderr)
        return 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))

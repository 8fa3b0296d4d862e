"""Command-line options of our Python applications (argparse), parsed the
way OpenFOAM's applications take them: an option's value may be a negative
number. argparse reads "-dz -25e-9" as the option -dz followed by an
option "-25e-9" and stops with "expected one argument" (its own test for a
negative number misses exponents); parse() joins such a pair into
"-dz=-25e-9" first, so that the application's range check says what is
wrong with the value (issue 19)."""

import argparse
import os
import re
import stat
import sys

from . import ranges


def notARegularFile(path):
    """What path is if it is there and not a regular file: "a directory",
    "a FIFO (named pipe)", "a socket", "a device" ("" if it is a regular
    file or is not there). Looked at with os.stat, without opening it:
    opening a FIFO blocks until a writer comes (issue 19, adv28 m16, ir06:
    a FIFO given as a file hung the application). The Python side of
    src/foamTools/fileKind.H; every file path a user gives to our Python
    applications, and every file foamDict.read reads, goes through it."""
    try:
        m = os.stat(path).st_mode
    except (OSError, ValueError):
        return ""
    if stat.S_ISREG(m):
        return ""
    if stat.S_ISDIR(m):
        return "a directory"
    if stat.S_ISFIFO(m):
        return "a FIFO (named pipe)"
    if stat.S_ISSOCK(m):
        return "a socket"
    if stat.S_ISCHR(m) or stat.S_ISBLK(m):
        return "a device"
    return "not a regular file"


# The sane sizes of the files a user gives, by kind (those of
# src/foamTools/fileKind.H): a dictionary or case file, a column table (a
# probe, force or peaks log, a reference), a gmsh mesh
DICTIONARY_LIMIT = 64 << 20
TABLE_LIMIT = 1 << 30
MESH_LIMIT = 256 << 20


def _sizeText(n):
    """A size in bytes as a short text: "3.2 GiB (3435973837 bytes)"."""
    v, u = float(n), 0
    units = ["bytes", "KiB", "MiB", "GiB", "TiB"]
    while v >= 1024 and u < 4:
        v /= 1024
        u += 1
    return "%d bytes" % n if u == 0 else "%.3g %s (%d bytes)" % (v, units[u], n)


def readRefusal(path, maxBytes, kind):
    """Why path may not be read as a file of its kind ("" if it may, or if
    it is not there: the reader's own message then), naming it: not a
    regular file ("'<path>' is a FIFO (named pipe), not a file: reading it
    would wait without end for a writer"; a device such as /dev/zero gives
    bytes without end), or larger than maxBytes (0: no limit), the sane
    size of its kind (DICTIONARY_LIMIT, TABLE_LIMIT, MESH_LIMIT). The one
    look of the Python package before a reader opens a user's file (issue
    19, adv52 p10); the C++ side's is fileKind::readRefusal
    (src/foamTools/fileKind.H), with the same words."""
    kind_ = notARegularFile(path)
    if kind_:
        why = "" if kind_ == "a directory" else \
            ": reading it would not end (a device such as /dev/zero gives " \
            "bytes without end) or would wait for input" \
            if kind_ == "a device" else \
            ": reading it would wait without end for a writer"
        return "'%s' is %s, not a file%s" % (path, kind_, why)
    try:
        size = os.stat(path).st_size
    except (OSError, ValueError):
        return ""
    if maxBytes and size > maxBytes:
        return "'%s' is %s, more than the %s a %s may be: is it the right " \
            "file?" % (path, _sizeText(size), _sizeText(maxBytes), kind)
    return ""


def fileProblem(path):
    """Why a path the user gives as a file cannot be read as one, '' if
    it can: "no such file", "a symbolic link to <target>, which is not
    there", or what it is ("a directory, not a file", "a device, not a
    file": /dev/null, /dev/zero; a FIFO, which would block the open). The
    one check of a file given to our Python applications before it is
    read (issue 19, adv45 b16, b26: a directory, a FIFO, /dev/zero and
    /dev/null were each "no such file")."""
    if not os.path.lexists(path):
        return "no such file"
    if not os.path.exists(path):
        return "a symbolic link to %s, which is not there" % os.readlink(path)
    kind = notARegularFile(path)
    return kind + ", not a file" if kind else ""


def _invalidCharacters(path):
    """The characters of path that OpenFOAM's file names drop (fileName::
    valid: white space, a quote) or change (a backslash, taken for a '/',
    adv32 u02), each once, named ("a space, '\"'"); "" if
    there are none."""
    names = []
    for c in path:
        if c in " \t\n\r\v\f\"'\\":
            name = {" ": "a space", "\t": "a tab", "\n": "a newline",
                    "\\": "a backslash"}.get(
                c, "'%s'" % c if c in "\"'" else repr(c))
            if name not in names:
                names.append(name)
    return ", ".join(names)


def casePathProblem(path, how="", logical=False):
    """The project's message for a case directory holding a character
    OpenFOAM's file names drop (a space, a quote, a tab, a newline), ""
    if it holds none: the Python side of foamTools::checkCasePath
    (src/foamTools/inputChecks.H, the same words). path is taken
    absolute and physical (os.path.realpath, as OpenFOAM's cwd()); how
    says how it was given (e.g. " (the working directory)"). Used by
    every Allrun (etc/RunFunctions allrunOptions) and pulseStudy before
    anything runs: OpenFOAM's applications in such a case end in
    "fileName::stripInvalid() called for invalid fileName", or run in
    another directory (issue 19, adv29 z4, z5). logical: path is taken
    as given (made absolute, not resolved): the shell's $PWD, through
    symbolic links, which OpenFOAM's applications take as the case when
    it names the working directory (adv38 x08: a link named "my case" to
    a folder without a space passed the physical check, then cellMesh
    died in "fileName::stripInvalid()")."""
    full = os.path.abspath(path) if logical else os.path.realpath(path)
    named = _invalidCharacters(full)
    if not named:
        return ""
    # OpenFOAM takes a backslash for a '/'
    kept = "".join("/" if c == "\\" else c for c in full
                   if c == "\\" or not _invalidCharacters(c))
    return ("the case directory \"%s\"%s holds %s, which OpenFOAM's file "
            "names cannot hold%s.\n    Nothing was read or written: rename "
            "the directory (or one above it) without such characters."
            % (full, how, named, " (it would run in \"%s\")" % kept
               if kept != full else ""))


def _numbers(s):
    """Whether s is one or more numbers (sweepCase -values "-1 -2")."""
    try:
        return len([float(x) for x in s.split()]) > 0
    except ValueError:
        return False


def joinNegativeValues(parser, argv):
    """argv with each option that takes one value and is followed by a
    negative number joined to it (-opt=-1e-9); the negative numbers among
    the values of an option of several values given a leading space."""
    takesValue = set()
    takesValues = {}
    for action in parser._actions:
        if action.option_strings and action.nargs is None \
                and action.const is None:
            takesValue.update(action.option_strings)
        elif action.option_strings and isinstance(action.nargs, int) \
                and action.nargs > 1:
            for o in action.option_strings:
                takesValues[o] = action.nargs
    out = []
    i = 0
    while i < len(argv):
        a = argv[i]
        if a in takesValue and i + 1 < len(argv) \
                and argv[i + 1].startswith("-") and _numbers(argv[i + 1]):
            out.append(a + "=" + argv[i + 1])
            i += 2
        elif a in takesValues:
            # an option of N values (incidentWindow.py --series T0 T1 DT):
            # a negative number among them is given a leading space, which
            # argparse takes as a value and float() reads (adv53 u14:
            # "--series 0 2 -1e-3" was "expected 3 arguments")
            out.append(a)
            for v in argv[i + 1:i + 1 + takesValues[a]]:
                out.append(" " + v if v.startswith("-") and _numbers(v)
                           else v)
            i += 1 + takesValues[a]
        else:
            out.append(a)
            i += 1
    return out


def repeatedOptions(parser, argv):
    """The options of argv given more than once that take one value or are
    switches (argparse keeps the last silently: "-np 2 -np 4" ran with 4;
    issue 19, pw42, op01, op02): [(option, [values])], by their first
    spelling; an option whose action appends or counts may repeat. argv
    as joinNegativeValues leaves it (-opt=value, -opt value)."""
    single = (argparse._StoreAction, argparse._StoreConstAction,
              argparse._StoreTrueAction, argparse._StoreFalseAction)
    seen = {}
    order = []
    i = 0
    while i < len(argv):
        a = argv[i]
        i += 1
        if a == "--":
            break
        if not a.startswith("-") or _numbers(a):
            continue
        name, eq, value = a.partition("=")
        action = parser._option_string_actions.get(name)
        if action is None or not isinstance(action, single):
            continue
        if not eq and action.nargs is None \
                and isinstance(action, argparse._StoreAction) \
                and i < len(argv):
            value = argv[i]
            i += 1
        if action not in seen:
            seen[action] = (name, [])
            order.append(action)
        seen[action][1].append(value)
    return [seen[a] for a in order if len(seen[a][1]) > 1]


def _optionNumbers(parser, argv):
    """(option, value, word, float(word)) for each word of each option
    value of argv that Python's float() reads (words: separated by
    whitespace, commas, colons, semicolons, brackets)."""
    i = 0
    while i < len(argv):
        a = argv[i]
        i += 1
        name, eq, value = a.partition("=")
        action = parser._option_string_actions.get(name)
        if action is None or action.nargs == 0:
            continue
        if not eq:
            if i >= len(argv):
                continue
            value = argv[i]
            i += 1
        for word in re.split(r"[\s,:;()\[\]]+", value):
            try:
                v = float(word)
            except ValueError:
                continue
            yield name, value, word, v


def numbersOutsideReader(parser, argv):
    """[(option, value, why)] for each option value of argv holding a
    number outside what OpenFOAM's reader takes (ranges.
    readerRangeProblem: 5e-324 or 1e308; issue 19, pv02: planeWave
    -dz 5e-324 was an OverflowError), as the C++ applications'
    checkOptions. Each whitespace, comma or colon separated word of the
    value is looked at."""
    out = []
    for name, value, word, v in _optionNumbers(parser, argv):
        why = ranges.readerRangeProblem(word, v)
        if why and (not out or out[-1][:2] != (name, value)):
            out.append((name, value, why))
    return out


def numbersNotPlain(parser, argv):
    """[(option, value, word)] for each option value of argv holding a
    word that Python's float() reads as a number but that is no plain
    decimal number: a digit other than ASCII 0-9 (Arabic-Indic
    '\u0661e-\u0669', full-width digits) or an underscore ('1_000').
    OpenFOAM's reader and the C++ applications take neither as a number:
    the value was accepted and written into a dictionary, which the
    solver then refused naming the dictionary, not the option (adv46b
    d35). The first such word of each value."""
    out = []
    for name, value, word, v in _optionNumbers(parser, argv):
        if (not word.isascii() or "_" in word) \
                and (not out or out[-1][:2] != (name, value)):
            out.append((name, value, word))
    return out


def valueWordProblem(word):
    """Why word, one value of an option that gives an entry's value (a
    number or a name; sweepCase -values), is not one OpenFOAM reads as the
    number it looks like, or None: a word beginning as a number must be a
    plain decimal number: a hexadecimal one ('0x1p-23', read as the tokens
    0 and x1p-23), one with a leading '+' (a token of its own), a list
    joined by commas ('1e-7,2e-7', read as 1e-07 followed by a word) are
    not; nor is zero with a minus sign ('-0', the same value as 0, read as
    -0: refused by an entry whose range begins above 0, accepted as 0
    otherwise). adv46b d42: each was copied and run, and the solver
    failed."""
    if not re.match(r"[+-]?\.?\d", word):
        return None
    if re.fullmatch(r"-?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?", word):
        if word.startswith("-") and float(word) == 0:
            return ("zero written with a minus sign (the same value as 0, "
                    "which OpenFOAM reads as -0): write 0")
        return None
    if "," in word:
        return ("a list joined by commas (OpenFOAM reads one number and "
                "then a word): give the values separated by spaces")
    if re.match(r"[+-]?0[xX]", word):
        return ("a hexadecimal number (OpenFOAM reads the prefix 0x as the "
                "end of the number 0): write it in decimal")
    if word.startswith("+"):
        return ("a number with a '+' sign (OpenFOAM reads the sign as a "
                "token of its own): write it without the sign")
    return ("not a plain decimal number (digits 0-9, one '.', an exponent "
            "e<digits>): OpenFOAM would not read it as one number")


def parse(parser, argv=None):
    """parser.parse_args of argv (default: the command line) with negative
    values taken as values, each option given at most once (a usage error
    naming a repeated one: repeatedOptions)."""
    argv = sys.argv[1:] if argv is None else argv
    # -help, the OpenFOAM applications' spelling, is argparse's --help (was:
    # "argument -h/--help: ignored explicit argument 'elp'", exit 2; adv30
    # sw01, kh01)
    if "--help" in parser._option_string_actions \
            and "-help" not in parser._option_string_actions:
        argv = ["--help" if a == "-help" else a for a in argv]
    argv = joinNegativeValues(parser, argv)
    for name, value, why in numbersOutsideReader(parser, argv):
        parser.error("option %s '%s': %s: give a value with 1e-300 < |x| "
                     "<= 1e+300 in the option's valid range (or 0, if the "
                     "range holds 0)" % (name, value, why))
    for name, value, word in numbersNotPlain(parser, argv):
        parser.error("option %s '%s': '%s' is not a plain decimal number "
                     "(digits 0-9 only, no '_': OpenFOAM would not read it "
                     "as a number)" % (name, value, word))
    for name, values in repeatedOptions(parser, argv):
        given = ", ".join("'%s'" % v for v in values if v)
        parser.error("option %s is given %d times%s: give it once (it "
                     "would take the last silently)"
                     % (name, len(values),
                        " (values %s)" % given if given else ""))
    return parser.parse_args(argv)

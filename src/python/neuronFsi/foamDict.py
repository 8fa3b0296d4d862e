"""OpenFOAM dictionary text: read into Python values, and replace or add one
entry in place (comments and layout of the rest of the file kept).

Used by calibrateCell and sweepCase (applications/utilities) and the
scripts. Only the subset of the format the project's dictionaries use:
nested sub-dictionaries, entries `key value...;`, lists `( ... )`, quoted
strings, // and /* */ comments, and #include "file", #sinclude "file" (or
#includeIfPresent) merged as OpenFOAM does (a later entry replaces an
earlier one, sub-dictionaries are merged) when the text is read from a file
by read(); environment variables in an included file's name are expanded
(e.g. "$PROJECT_DIR/etc/caseDicts/cellMaterials/table"). No $variables in
entries, no other directives. A keyword given twice in one scope of one
text is a DictError (OpenFOAM would keep the last silently; an entry of an
included file replaced by the text is not a duplicate), as in the C++
readers (src/foamTools/keywordCheck.H).

check_keywords(d, valid, where) refuses a keyword that is not valid with
the closest valid one when it is close (closest: the C++ readers' rule of
src/foamTools/closestKeyword.H, the same distance and threshold).
"""

import fnmatch
import math
import os
import re
from . import options, ranges

_TOKEN = re.compile(r'''
    (?P<ws>\s+)
  | (?P<lc>//[^\n]*)
  | (?P<bc>/\*.*?\*/)
  | (?P<str>"[^"]*")
  | (?P<punct>[{}();])
  | (?P<word>[^\s{}();"]+)
''', re.S | re.X)


class DictError(Exception):
    """A dictionary that cannot be read; the message names file and place."""


class BelowReader(float):
    """A number of a dictionary that OpenFOAM's reader takes as 0: not zero
    as written, of magnitude at most 1e-300 (4.9e-324, 1e-300, 1e-400), or
    does not read: above 1e300 (1e308, 1e309; beyond()). Its value is 0.0
    (what the solvers would read for the first); text is the number as
    written, where the file and line, entry the entry's path. Returned by
    parse (read, read_checked) with belowReader=True, for a reader that
    names the entry's own valid range (problem); refuseBelowReader refuses
    the others (adv47b f22, f30: "give 0 or a value ... in the entry's valid
    range" without the range, and 0 advised where the entry refuses it)."""

    def __new__(cls, text, where, entry):
        self = float.__new__(cls, 0.0)
        self.text, self.where, self.entry = text, where, entry
        return self

    def __repr__(self):
        return self.text

    __str__ = __repr__

    def problem(self, interval, unit=""):
        """The message's text naming the entry's valid range interval (a
        ranges.Interval or its text; unit with its leading space): 0
        suggested only when the range holds it."""
        if not isinstance(interval, ranges.Interval):
            interval = ranges.Interval(interval)
        if self.beyond():
            give = "give a value in it"
        elif 0.0 in interval:
            give = "give 0, or a value of magnitude above 1e-300 in it"
        else:
            give = "give a value in it" + (
                " above 1e-300" if interval.low <= ranges.READER_SMALLEST
                else "")
        return ("%s: %s = %s%s %s; the entry's valid range is %s%s: %s"
                % (self.where, self.what(), self.text, unit,
                   ranges.readerRangeProblem(self.text, float(self.text)),
                   interval, unit, give))

    def what(self):
        return "a value of the list" if self.entry is None \
            else "entry '%s'" % self.entry

    def beyond(self):
        """True for a number above the reader's largest magnitude (not
        read), False for one it reads as 0."""
        return not abs(float(self.text)) <= ranges.READER_LARGEST


def belowReaderLeft(d, keep=()):
    """The BelowReader values of d (a parsed dictionary, a list or a
    value) whose entry path matches none of the fnmatch patterns keep,
    in the file's order."""
    out = []
    if isinstance(d, BelowReader):
        if not any(fnmatch.fnmatchcase(d.entry or "", k) for k in keep):
            out.append(d)
    elif isinstance(d, dict):
        for v in d.values():
            out += belowReaderLeft(v, keep)
    elif isinstance(d, list):
        for v in d:
            out += belowReaderLeft(v, keep)
    return out


def refuseBelowReader(d, error, keep=()):
    """error(message) for the first BelowReader value of d outside the
    entries keep (fnmatch patterns of entry paths, e.g. "targets/*/value"),
    those whose reader names their range (BelowReader.problem): the range of
    any other entry is not known here, and 0 is advised only as one value
    among those the entry may take."""
    left = belowReaderLeft(d, keep)
    if left:
        v = left[0]
        raise error("%s: %s = %s %s: %s"
                    % (v.where, v.what(), v.text,
                       ranges.readerRangeProblem(v.text, float(v.text)),
                       "give a value with |x| <= 1e+300 in the entry's "
                       "valid range" if v.beyond() else
                       "give a value with 1e-300 < |x| <= 1e+300 in the "
                       "entry's valid range (or 0, if the range holds 0)"))



def tokens(text, name="<text>"):
    """(token, start, end) of the text without blanks and comments."""
    out = []
    pos = 0
    while pos < len(text):
        m = _TOKEN.match(text, pos)
        if not m:
            line = text.count("\n", 0, pos) + 1
            raise DictError("%s, line %d: cannot read '%s'"
                            % (name, line, text[pos:pos + 20]))
        if m.lastgroup in ("str", "punct", "word"):
            out.append((m.group(), m.start(), m.end()))
        pos = m.end()
    return out


def edit_distance(a, b):
    """Optimal string alignment distance: insertions, deletions,
    substitutions and swaps of two adjacent characters count 1 each."""
    d = [[0]*(len(b) + 1) for _ in range(len(a) + 1)]
    for i in range(len(a) + 1):
        d[i][0] = i
    for j in range(len(b) + 1):
        d[0][j] = j
    for i in range(1, len(a) + 1):
        for j in range(1, len(b) + 1):
            d[i][j] = min(d[i - 1][j] + 1, d[i][j - 1] + 1,
                          d[i - 1][j - 1] + (a[i - 1] != b[j - 1]))
            if i > 1 and j > 1 and a[i - 1] == b[j - 2] \
                    and a[i - 2] == b[j - 1]:
                d[i][j] = min(d[i][j], d[i - 2][j - 2] + 1)
    return d[len(a)][len(b)]


def closest(key, valid):
    """The valid keyword nearest to key, None unless within
    max(2, len(key)//3) edits; ties go to the first in valid."""
    best, best_d = None, max(2, len(key)//3) + 1
    for v in valid:
        dist = edit_distance(key, v)
        if dist < best_d:
            best, best_d = v, dist
    return best


def did_you_mean(key, valid):
    """"; did you mean 'X'?" for the closest valid keyword, or ""."""
    c = closest(key, valid)
    return "" if c is None else "; did you mean '%s'?" % c


def check_keywords(d, valid, where):
    """DictError naming where (the file and scope), the first keyword of
    d that is not in valid, the closest valid one and the valid ones."""
    for k in d:
        if k not in valid:
            raise DictError("%s: unknown entry '%s'%s; valid entries: (%s)"
                            % (where, k, did_you_mean(k, list(valid)),
                               " ".join(valid)))


def _line(text, pos):
    return text.count("\n", 0, pos) + 1


def _value(tok):
    if tok.startswith('"'):
        return tok[1:-1]
    for conv in (int, float):
        try:
            return conv(tok)
        except ValueError:
            pass
    low = tok.lower()
    if low in ("yes", "on", "true"):
        return True
    if low in ("no", "off", "false"):
        return False
    return tok


def _merge(d, new):
    """OpenFOAM's merge of a dictionary read later into d."""
    for k, v in new.items():
        if isinstance(v, dict) and isinstance(d.get(k), dict):
            _merge(d[k], v)
        else:
            d[k] = v


def parse(text, name="<text>", base=None, included=None, belowReader=False):
    """Nested dict of the file. An entry of one token is that value (int,
    float, bool for yes/no/true/false/on/off, or str); of several tokens or
    a list, a Python list; the FoamFile header is dropped. Include
    directives name files relative to the directory base. With a list
    `included`, include directives are not followed: the text's own
    entries only, the directives' file names appended to the list.
    A number OpenFOAM reads as 0 (not zero, magnitude at most 1e-300) is a
    DictError, or with belowReader a BelowReader value (its reader names
    the entry's range; refuseBelowReader the others)."""
    toks = tokens(text, name)
    i = [0]

    def err(msg, k):
        pos = toks[k][1] if k < len(toks) else len(text)
        raise DictError("%s, line %d: %s" % (name, _line(text, pos), msg))

    entry = [None]      # the entry being read, for the messages

    def value(k):
        t = toks[k][0]
        v = _value(t)
        if isinstance(v, float) and not math.isfinite(v) \
                and t.lower().lstrip("+-") in ("nan", "inf", "infinity"):
            return t            # a word, as OpenFOAM reads it
        why = ranges.readerRangeProblem(t, v) if not t.startswith('"') \
            else ""
        # below the reader (read as 0) or beyond it (an error): named by
        # the entry's reader with its range (adv48a h15: 1e308 named with
        # the reader's limits only)
        if why and belowReader:
            return BelowReader(t, "%s, line %d" % (name, _line(
                text, toks[k][1])), entry[0])
        if why:
            what = "a value of the list" if entry[0] is None \
                else "entry '%s'" % entry[0]
            err("%s = %s %s: give a value with 1e-300 < |x| <= 1e+300 in "
                "the entry's valid range (or 0, if the range holds 0)"
                % (what, t, why), k)
        return v

    def parse_list():
        items = []
        while True:
            if i[0] >= len(toks):
                err("unclosed '('", i[0] - 1)
            t = toks[i[0]][0]
            i[0] += 1
            if t == ")":
                return items
            if t == "(":
                items.append(parse_list())
            elif t in "{};":
                err("unexpected '%s' in a list" % t, i[0] - 1)
            else:
                items.append(value(i[0] - 1))

    def directive(key):
        if key not in ("#include", "#sinclude", "#includeIfPresent"):
            err("unsupported directive '%s' (valid: #include, #sinclude, "
                "#includeIfPresent)" % key, i[0] - 1)
        if i[0] >= len(toks) or not toks[i[0]][0].startswith('"'):
            err("%s needs a quoted file name" % key, i[0] - 1)
        if included is not None:
            included.append('%s %s' % (key, toks[i[0]][0]))
            i[0] += 1
            return {}
        if base is None:
            err("%s in a text that is not a file" % key, i[0] - 1)
        path = os.path.join(base, os.path.expandvars(toks[i[0]][0][1:-1]))
        i[0] += 1
        if not os.path.exists(path):
            if key == "#include":
                err("%s: no file %s" % (key, path), i[0] - 1)
            return {}
        return read(path, belowReader)

    def parse_dict(closing, scope):
        d = {}
        seen = {}

        def once(key, k):
            if key in seen:
                err("entry '%s' is given twice in %s (first on line %d; "
                    "OpenFOAM would keep the last silently): give it once"
                    % (key, "'%s'" % "/".join(scope) if scope
                       else "the top level", seen[key]), k)
            seen[key] = _line(text, toks[k][1])

        while i[0] < len(toks):
            key, _, _ = toks[i[0]]
            if key == "}":
                if not closing:
                    err("unexpected '}'", i[0])
                i[0] += 1
                return d
            if key in "{();":
                err("expected a keyword, found '%s'" % key, i[0])
            i[0] += 1
            if key.startswith("#"):
                _merge(d, directive(key))
                continue
            key = _value(key) if key.startswith('"') else key
            once(key, i[0] - 1)
            if i[0] < len(toks) and toks[i[0]][0] == "{":
                i[0] += 1
                _merge(d, {key: parse_dict(True, scope + [key])})
                continue
            vals = []
            entry[0] = "/".join(scope + [str(key)])
            while True:
                if i[0] >= len(toks):
                    err("entry '%s' has no closing ';'" % key, i[0] - 1)
                t = toks[i[0]][0]
                i[0] += 1
                if t == ";":
                    break
                if t == "(":
                    vals.append(parse_list())
                elif t in "{})":
                    err("unexpected '%s' in entry '%s'" % (t, key), i[0] - 1)
                else:
                    vals.append(value(i[0] - 1))
            d[key] = vals[0] if len(vals) == 1 else vals
            entry[0] = None
        if closing:
            err("unclosed '{'", len(toks))
        return d

    d = parse_dict(False, [])
    d.pop("FoamFile", None)
    return d


def read(path, belowReader=False):
    """Nested dict of a dictionary file (see parse), includes merged. A path
    that is not a regular file (a FIFO would block the open) is a
    DictError naming what it is."""
    kind = options.notARegularFile(path)
    if kind:
        raise DictError("%s is %s, not a file%s" % (
            path, kind, "" if kind == "a directory" else
            ": reading it would wait without end for a writer"))
    refusal = options.readRefusal(path, options.DICTIONARY_LIMIT,
                                  "dictionary")
    if refusal:
        raise DictError(refusal)
    return parse(fileText(path), path, os.path.dirname(path) or ".",
                 belowReader=belowReader)


def fileText(path):
    """The text of a dictionary file as OpenFOAM reads it, byte by byte:
    UTF-8, else Latin-1 (one character per byte: a comment written by an
    ISO-8859-1 editor, "// a size in \\xb5m", is no error to OpenFOAM;
    adv45 b48: a Python traceback, UnicodeDecodeError, in pulseStudy,
    calibrateCell, sweepCase and paperFigures). A file beginning with a
    UTF-8 byte-order mark is a DictError naming it (OpenFOAM reads the mark
    as part of the first keyword; the C++ tools refuse it alike). A file with a NUL or
    another control character (a binary file given as a dictionary,
    adv45 b16: a traceback) is a DictError naming the file and the byte.
    The one reader of a dictionary's text for our Python tools."""
    with open(path, "rb") as f:
        data = f.read()
    if data.startswith(b"\xef\xbb\xbf"):
        # OpenFOAM v1912 reads the mark as part of the first keyword (the
        # header, or the first entry, lost without a word); the solvers'
        # scan refuses it too (foamTools::checkNumbers; adv45 c02: "line
        # 9: unexpected '{' in entry '\ufeff/*---'")
        raise DictError("%s, line 1: the file begins with a UTF-8 byte-order "
                        "mark (bytes EF BB BF, as some Windows editors "
                        "save), which OpenFOAM reads as part of the first "
                        "keyword: save it as UTF-8 without a byte-order "
                        "mark" % path)
    bad = re.search(rb"[\x00-\x08\x0e-\x1f\x7f]", data)
    if bad:
        raise DictError("%s is not a text dictionary: byte %d (0x%02x) is a "
                        "control character; expected an OpenFOAM dictionary"
                        % (path, bad.start(), data[bad.start()]))
    try:
        return data.decode("utf-8")
    except UnicodeDecodeError:
        return data.decode("latin-1")


def own_entry(path, keys):
    """Whether the file at path writes entry keys (e.g. ['materials',
    'nucleus', 'C10']) in its own text, not through an include directive:
    (True, []) if it does, else (False, the file's include directives).
    Only an entry of the file's own text can be set in it (set_entry)."""
    included = []
    d = parse(fileText(path), path, included=included)
    for k in keys:
        if not isinstance(d, dict) or k not in d:
            return False, included
        d = d[k]
    return True, []


def read_checked(path, valid, required, error, belowReader=False):
    """read(path) with its keywords checked (check_keywords) and the
    required ones present; any fault raises error(message), the message
    naming the file (a missing file or what the path is instead, an
    unknown keyword with the closest valid one, a missing entry).
    belowReader: as in parse (the caller refuses what remains with
    refuseBelowReader)."""
    why = options.fileProblem(path)
    if why:
        raise error("%s: %s" % (path, why))
    try:
        d = read(path, belowReader)
        check_keywords(d, valid, path)
    except DictError as err:
        raise error(str(err))
    for k in required:
        if k not in d:
            raise error("%s: no entry '%s'%s" % (
                path, k, " (the file is empty)"
                if os.path.getsize(path) == 0 else ""))
    return d


def set_entry(text, path, value, name="<text>"):
    """Text with entry `path` (keys from the top, e.g. ['nucleus', 'C10'])
    set to `value` (the text between the keyword and ';'). An existing entry
    is replaced; a missing one is added at the end of its sub-dictionary,
    which must exist."""
    toks = tokens(text, name)
    depth = 0
    want = 0          # index in path of the key looked for at this depth
    start = 0         # insertion point: end of the top level by default
    end_of_dict = len(text)
    k = 0
    while k < len(toks):
        t, s, e = toks[k]
        if t == "}":
            if depth == want and want > 0:
                end_of_dict = s
                break
            depth -= 1
        elif t in ("{", "("):
            depth += 1
        elif t == ")":
            depth -= 1
        elif t == ";":
            pass
        elif depth == want and (k == 0 or toks[k - 1][0] in ";{}"):
            if t.strip('"') == path[want]:
                if want == len(path) - 1:
                    if k + 1 < len(toks) and toks[k + 1][0] == "{":
                        raise DictError("%s: '%s' is a sub-dictionary, not "
                                        "an entry" % (name, "/".join(path)))
                    j = k + 1
                    level = 0
                    while j < len(toks) and not (toks[j][0] == ";"
                                                 and level == 0):
                        level += {"(": 1, ")": -1}.get(toks[j][0], 0)
                        j += 1
                    if j == len(toks):
                        raise DictError("%s: entry '%s' has no ';'"
                                        % (name, "/".join(path)))
                    return text[:e] + " " + str(value) + text[toks[j][1]:]
                if k + 1 < len(toks) and toks[k + 1][0] == "{":
                    want += 1
                    depth += 1
                    k += 2
                    continue
        k += 1
    if want < len(path) - 1:
        raise DictError("%s: no sub-dictionary '%s'"
                        % (name, "/".join(path[:want + 1])))
    indent = "    " * want
    new = "%s%s %s;\n" % (indent, path[-1], value)
    if want == 0:
        sep = "" if text.endswith("\n") else "\n"
        return text + sep + new
    # before the closing brace of the sub-dictionary, on its own line
    line_start = text.rfind("\n", 0, end_of_dict) + 1
    return text[:line_start] + new + text[line_start:]


def format_value(v):
    """Dictionary text of a Python value (numbers with full precision)."""
    if isinstance(v, bool):
        return "yes" if v else "no"
    if isinstance(v, float):
        return repr(v)
    if isinstance(v, (list, tuple)):
        return "(" + " ".join(format_value(x) for x in v) + ")"
    return str(v)


def _subdict_span(text, name, name_of_text):
    """(start, end) of the top-level sub-dictionary `name` in text, from
    its keyword to its closing brace; None when there is none."""
    toks = tokens(text, name_of_text)
    depth = 0
    for k, (t, s, e) in enumerate(toks):
        if t in ("{", "("):
            depth += 1
        elif t in ("}", ")"):
            depth -= 1
        elif (depth == 0 and t.strip('"') == name and k + 1 < len(toks)
              and toks[k + 1][0] == "{"
              and (k == 0 or toks[k - 1][0] in ";{}")):
            level = 0
            for t2, s2, e2 in toks[k + 1:]:
                level += {"{": 1, "}": -1}.get(t2, 0)
                if level == 0:
                    return s, e2
            raise DictError("%s: unclosed sub-dictionary '%s'"
                            % (name_of_text, name))
    return None


def set_subdict(text, path, entries, name_of_text="<text>", units={},
                indent=""):
    """Text with the sub-dictionary `path` (a name at the top level, or a
    list of names from the top, e.g. ['materials', 'nucleus'], whose
    parents must exist) replaced by (or, when missing, appended as) one
    holding `entries` (dict key -> value, with a unit comment from `units`
    where given)."""
    path = [path] if isinstance(path, str) else list(path)
    if len(path) > 1:
        span = _subdict_span(text, path[0], name_of_text)
        if span is None:
            raise DictError("%s: no sub-dictionary '%s'"
                            % (name_of_text, path[0]))
        s, e = span
        i = text.index("{", s) + 1
        j = text.rindex("}", s, e)
        return text[:i] + set_subdict(
            text[i:j], path[1:], entries, name_of_text, units,
            indent + "    ") + text[j:]
    name = path[0]
    body = "%s%s\n%s{\n%s%s}" % (indent, name, indent, "".join(
        "%s    %-5s %s;%s\n" % (indent, k, format_value(v),
                              "  // [%s]" % units[k] if k in units else "")
        for k, v in entries.items()), indent)
    span = _subdict_span(text, name, name_of_text)
    if span is not None:
        s, e = span
        line = text.rfind("\n", 0, s) + 1
        start = line if not text[line:s].strip() else s
        return text[:start] + body + text[e:]
    if indent:
        return text.rstrip("\n") + "\n" + body + "\n"
    # before the closing '// ****' banner when there is one
    end = re.search(r"\n// \*+ //\s*$", text)
    if end:
        return text[:end.start()].rstrip("\n") + "\n\n" + body + "\n" \
            + text[end.start():]
    return text.rstrip("\n") + "\n\n" + body + "\n"

"""A valid range written as in mathematics, "(0, 1]", "[1, inf)": the one
form in which our Python code states and checks a range (the Allrun
options, neuronFsi.allrunOptions; calibrateCell's settings); and the
magnitudes of a number OpenFOAM's reader takes (readerRangeProblem: every
number of a dictionary, foamDict, and of a command-line option, options)."""

import math
import re

_FORM = re.compile(r"([(\[])\s*([^,]+?)\s*,\s*([^)\]]+?)\s*([)\]])\Z")


def _bound(text):
    t = text.strip()
    if t in ("inf", "+inf"):
        return math.inf
    if t == "-inf":
        return -math.inf
    return float(t)


class Interval:
    """An interval: ( ) open, [ ] closed ends, inf for no bound."""

    def __init__(self, text):
        m = _FORM.match(text.strip())
        if not m:
            raise ValueError("'%s' is not an interval such as (0, 1] or "
                             "[1, inf)" % text)
        self.lowClosed = m.group(1) == "["
        self.low = _bound(m.group(2))
        self.high = _bound(m.group(3))
        self.highClosed = m.group(4) == "]"
        self.text = "%s%s, %s%s" % m.groups()

    def __contains__(self, x):
        """Whether the number x is finite and inside."""
        return math.isfinite(x) \
            and (x >= self.low if self.lowClosed else x > self.low) \
            and (x <= self.high if self.highClosed else x < self.high)

    def __str__(self):
        return self.text


# The magnitudes OpenFOAM's reader of a number takes (ScalarRead: above
# 1e300 an error, non-zero at most 1e-300 read as 0 silently): the limits of
# src/foamTools/inputChecks.H (readerLargest, readerSmallest), so that an
# input means the same to the Python tools as to the solvers (issue 19:
# 5e-324 in a dictionary or an option was a ZeroDivisionError or an
# OverflowError in the scripts, 0 in the solvers)
READER_LARGEST = 1e300
READER_SMALLEST = 1e-300


def readerRangeProblem(token, v):
    """Why the number v written as token is outside what OpenFOAM's reader
    takes as written ("" if it is inside, or not a number): above
    READER_LARGEST (or beyond a double), or not zero and at most
    READER_SMALLEST (a denormal such as 5e-324, or 1e-400 which Python
    reads as 0). The words of foamTools::readerRangeText."""
    if isinstance(v, bool) or not isinstance(v, (int, float)) \
            or (isinstance(v, float) and math.isnan(v)):
        return ""
    mantissa = re.split("[eE]", token, maxsplit=1)[0]
    nonzero = any(c in "123456789" for c in mantissa)
    if abs(v) > READER_LARGEST:
        return ("is beyond the range of a number (OpenFOAM reads |x| <= "
                "1e+300; a double holds |x| <= 1.79769e+308)")
    if nonzero and abs(v) <= READER_SMALLEST:
        return ("is below the smallest magnitude OpenFOAM reads (1e-300): "
                "it would be read as 0")
    return ""


def countText(x):
    """The text of a limit on a count (maxSteps): a whole number with all
    its digits below 1e15 (1e6 as "1000000", not "1e+06"), else %g; the
    words of foamTools::countText."""
    if isinstance(x, (int, float)) and math.isfinite(x) \
            and x == math.floor(x) and abs(x) < 1e15:
        return "%d" % x
    return "%g" % x


def countAbove(x, limit):
    """The text of an estimated count x compared with the limit it exceeds:
    3 significant digits, or the least whole count (ceil) when those would
    not read above the limit (adv47b f47: "about 232 time steps ... above
    the limit of 232" for an estimate 232.x), so that the limit set to the
    number printed is no longer refused."""
    least = math.ceil(x)
    text = "%.3g" % least
    return text if float(text) > limit else "%d" % least

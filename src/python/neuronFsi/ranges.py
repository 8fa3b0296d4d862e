"""A valid range written as in mathematics, "(0, 1]", "[1, inf)": the one
form in which our Python code states and checks a range (the Allrun
options, neuronFsi.allrunOptions; calibrateCell's settings)."""

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

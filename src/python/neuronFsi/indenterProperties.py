"""constant/indenterProperties of an indentation case: its loading table
(the `protocol` list of rows `(stage kind rate amount)`) replaced by a
shorter one, for the tests and studies that run a case on a short table."""

import re


class ProtocolError(Exception):
    """A text without a protocol table; the message names it."""


def protocolText(rows):
    """The protocol entry of rows (stage, kind, rate, amount), each a
    string as it is to stand in the file, in the tutorials' columns."""
    return ("protocol\n(\n"
            + "".join(f"    ({stage:<4}{kind:<8}{rate:<8}{amount})\n"
                      for stage, kind, rate, amount in rows)
            + ");")


def setProtocol(text, rows, name="<text>"):
    """text with its protocol table replaced by rows (protocolText)."""
    new, n = re.subn(r"protocol\s*\(.*\);", lambda m: protocolText(rows),
                     text, flags=re.S)
    if n == 0:
        raise ProtocolError(f"{name}: no protocol table "
                            "(protocol ( ... );)")
    return new


def protocolDuration(rows, firstAmount=None):
    """The duration [s] of a protocol's rows (stage, kind, rate, amount)
    as cellIndentationFoam runs them (src/solid/drivers/
    IndentationProtocol.H): a hold lasts its amount [s], a load or unload
    row amount/rate (amount [m], rate [m/s]). firstAmount replaces the
    first row's amount (calibrateCell's delta0). None when a row is not
    such a row (its reader names it)."""
    total = 0.0
    for k, row in enumerate(rows):
        try:
            kind, rate, amount = str(row[1]), float(row[2]), float(row[3])
        except (IndexError, TypeError, ValueError):
            return None
        if k == 0 and firstAmount is not None:
            amount = float(firstAmount)
        if kind == "hold":
            total += amount
        elif kind in ("load", "unload") and rate > 0:
            total += amount/rate
        else:
            return None
    return total


_ROMAN = ("i", "ii", "iii", "iv", "v", "vi", "vii", "viii", "ix", "x")


def protocolPeakLabels(rows):
    """The labels of peaks.dat that cellIndentationFoam writes for a
    protocol's rows (stage, kind, rate, amount), in order, as
    src/solid/drivers/IndentationProtocol.C (peaks) and IndentationDriver.C
    give them: a load row followed by an unload row of its stage is a peak
    '<stage>,i', ',ii', ... (counted while the peaks' stage stays the
    same; from the 11th '<stage>,11'), a hold row that ends its stage
    (the last row, or the next row of another stage) 'end<stage>'. None
    when a row is not such a row (its reader names it)."""
    labels = []
    try:
        rows = [(str(r[0]), str(r[1])) for r in rows]
    except (IndexError, TypeError):
        return None
    stage, count = None, 0
    for i, (st, kind) in enumerate(rows):
        nxt = rows[i + 1] if i + 1 < len(rows) else None
        if kind == "load" and nxt is not None and nxt[1] == "unload" \
                and nxt[0] == st:
            count = count + 1 if st == stage else 0
            stage = st
            labels.append("%s,%s" % (st, _ROMAN[count] if count < 10
                                     else str(count + 1)))
        elif kind == "hold" and (nxt is None or nxt[0] != st):
            labels.append("end" + st)
    return labels

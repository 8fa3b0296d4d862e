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

#!/usr/bin/python3
"""Shorten the loading table of an indentation case in a scratch copy.

usage: setProtocol.py FILE --smoke
       setProtocol.py FILE ROW...
  FILE     the copy's constant/indenterProperties (edited in place)
  --smoke  the smoke table of tests/indentation/smokeIndentation.sh and
           tests/tutorials/cleanTree.sh: load 0.3 um at 0.3 um/s, hold
           1 s, one +-0.5 um cycle at 10 um/s; maxDepthIncrement 0.1 um,
           forceTarget 0.02 nN
  ROW      one row "stage kind rate amount", e.g. "A load 10e-6 5e-6"
           (rate [m/s], amount [m]; a hold: rate 0, amount [s])
"""
import re
import sys

from neuronFsi import script  # noqa: E402
script.guard()  # an input's error: one line, exit 1 (fix19k: every script)
from neuronFsi.indenterProperties import ProtocolError, setProtocol

SMOKE = [("A", "load", "0.3e-6", "0.3e-6"), ("B", "hold", "0", "1"),
         ("C1", "load", "10e-6", "0.5e-6"), ("C1", "unload", "10e-6",
                                              "0.5e-6")]
# the smoke table's entries, replaced wherever "<key> <value>;" stands
SMOKE_ENTRIES = {"maxDepthIncrement": "0.1e-6", "forceTarget": "0.02e-9"}

if len(sys.argv) < 3:
    sys.exit(__doc__)
path, args = sys.argv[1], sys.argv[2:]
if args == ["--smoke"]:
    rows, entries = SMOKE, SMOKE_ENTRIES
else:
    rows = [tuple(a.split()) for a in args]
    bad = [a for a, r in zip(args, rows) if len(r) != 4]
    if bad:
        sys.exit(f"setProtocol.py: row {bad[0]!r}: four words wanted "
                 "(stage kind rate amount)")
    entries = {}
with open(path) as f:
    text = f.read()
try:
    text = setProtocol(text, rows, path)
except ProtocolError as err:
    sys.exit(f"setProtocol.py: {err}")
for key, value in entries.items():
    text = re.sub(key + r"\s+[^;]*;", f"{key} {value};", text)
with open(path, "w") as f:
    f.write(text)

#!/usr/bin/python3
"""mkTable.py VERDICTS...: the markdown table of this pass's verdict files ("id class verdict run note"); a case given
in several files keeps its last line (a case re-run after a correction), sorted by id."""
import sys
rows = {}
for f in sys.argv[1:]:
    for line in open(f):
        if line.startswith('#') or not line.strip():
            continue
        cid, cls, verdict, run, note = line.rstrip('\n').split(None, 4)
        rows[cid] = (cls, verdict.replace('-low', ' low'), run, note)
print("| id | class | verdict | what happened |\n| --- | --- | --- | --- |")
for cid in sorted(rows):
    cls, verdict, run, note = rows[cid]
    print("| %s | %s | %s | (%s) %s |" % (cid, cls, verdict, run, note.replace('|', '/')))

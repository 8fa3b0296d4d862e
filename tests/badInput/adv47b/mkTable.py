#!/usr/bin/python3
"""mkTable.py VERDICTS: the markdown table of a verdicts file ("id verdict note"), each case's class from its header
(adv46b's mkTable.py for this folder's cases; a leading "class ...:" or "environment:" of the note is left out)."""
import re, sys, os
here = os.path.dirname(os.path.abspath(__file__))
print("| id | class | verdict | what happened |\n| --- | --- | --- | --- |")
for line in open(sys.argv[1]):
    if line.startswith('#') or not line.strip():
        continue
    cid, verdict, note = (line.rstrip('\n').split(None, 2) + [''])[:3]
    head = next(l for l in open(os.path.join(here, 'cases', cid + '.sh')) if l.startswith('# ' + cid + ' '))
    m = re.search(r'\((class [^,;)]*|environment)', head)
    cls = m.group(1).replace('class ', '') if m else '?'
    note = re.sub(r'^(\([^)]*\) )?(class [^:]*|environment): ', r'\1', note)
    print("| %s | %s | %s | %s |" % (cid, cls, verdict.replace('(low)', ' low'), note.replace('|', '/')))

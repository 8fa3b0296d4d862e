#!/usr/bin/python3
"""mkTable.py VERDICTS: the markdown table of a verdicts file (id verdict note), with each case's class from its header."""
import re, sys, os
here = os.path.dirname(os.path.abspath(__file__))
print("| id | class | verdict | what happened |\n| --- | --- | --- | --- |")
for line in open(sys.argv[1]):
    if line.startswith('#') or not line.strip():
        continue
    cid, verdict, note = (line.rstrip('\n').split(None, 2) + [''])[:3]
    head = open(os.path.join(here, 'cases', cid + '.sh')).read().splitlines()[1]
    m = re.search(r'\(class ([^,;)]*)', head)
    print("| %s | %s | %s | %s |" % (cid, m.group(1) if m else '?', verdict.replace('-low', ' low'), note.replace('|', '/')))

#!/usr/bin/python3
"""everNonOk.py: every case of adv35-adv45 that any pass's report.md (tables) judged other than OK at some time: a table
row whose cell starts with CRASH/HANG/SILENT/DATALOSS/UNCLEAR (after '**'), its ids taken from the row's first cell (and
from the third cell of adv35's verdict-count table); an id without 'advNN' belongs to the report's pass. Prints "PASS ID"
lines of cases that exist (tests/badInput/PASS/cases/ID.sh), sorted."""
import re, os, glob
bi = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
bad = ('CRASH', 'HANG', 'SILENT', 'DATALOSS', 'UNCLEAR')
out = set()
for rep in sorted(glob.glob(bi + '/adv3*/report.md') + glob.glob(bi + '/adv4[0-5]/report.md')):
    P = rep.split('/')[-2]
    for l in open(rep):
        if not l.startswith('|'): continue
        cells = [c.strip().strip('*').strip() for c in l.strip().strip('|').split('|')]
        if not any(c.split(' ')[0].strip('*,;()') in bad for c in cells[1:] if c): continue
        srcs = [cells[0]] + ([cells[2]] if len(cells) > 2 and cells[0] in bad else [])
        for s in srcs:
            cur = P
            for tok in re.findall(r'adv3[5-9]|adv4[0-5]|\b[a-z]\d{2,3}\b', s):
                if tok.startswith('adv'): cur = tok; continue
                for p in (cur,):
                    if os.path.exists('%s/%s/cases/%s.sh' % (bi, p, tok)): out.add((p, tok))
for p, i in sorted(out): print(p, i)

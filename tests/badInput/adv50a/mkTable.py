#!/usr/bin/python3
"""mkTable.py [-t] DIR... (adv50a): the counts of my verdicts (verdicts.txt: "DIR PASS_ID | VERDICT | note", my judgement
of each output, read; the last line of a DIR PASS_ID wins) for the outputs in out/DIR..., per pass (the pass whose cases
folder holds the case) and verdict class (OK, CRASH, HANG, SILENT, DATALOSS, UNCLEAR; "(low)" counted in its class,
"n/r" counted apart); DIR:PASS_ID takes that output only, DIR-PASS_ID[,PASS_ID] all of DIR but those; -t: list the outputs with no verdict yet. Written, not adv48a's: that one calls adv47a's compare.py,
whose normalisation does not know this pass's base prefix."""
import sys, os, glob, collections
here = os.path.dirname(os.path.abspath(__file__)); args = [a for a in sys.argv[1:] if a != '-t']
v = {}
for l in open(os.path.join(here, 'verdicts.txt')):
    if l.startswith('#') or '|' not in l: continue
    k, verdict, _ = [x.strip() for x in l.split('|', 2)]; v[tuple(k.split())] = verdict
C = ['OK', 'CRASH', 'HANG', 'SILENT', 'DATALOSS', 'UNCLEAR', 'n/r']
cnt = collections.defaultdict(collections.Counter); todo = []
for a in args:
    d, only, skip = a, None, set()
    if ':' in a: d, only = a.split(':', 1)
    elif '-' in a: d, rest = a.split('-', 1); skip = set(rest.split(','))
    for f in sorted(glob.glob(os.path.join(here, 'out', d, '*.txt'))):
        k = os.path.basename(f)[:-4]
        if (only and k != only) or k in skip: continue
        if (d, k) not in v: todo.append('%s %s' % (d, k)); continue
        cls = next(c for c in C if v[(d, k)].startswith(c)); cnt[k.split('_')[0]][cls] += 1
print('| pass | cases | ' + ' | '.join(C) + ' |'); print('| --- ' * (len(C) + 2) + '|')
tot = collections.Counter()
for p in sorted(cnt):
    tot.update(cnt[p]); print('| %s | %d | ' % (p, sum(cnt[p].values())) + ' | '.join(str(cnt[p][c]) for c in C) + ' |')
print('| **total** | %d | ' % sum(tot.values()) + ' | '.join(str(tot[c]) for c in C) + ' |')
if '-t' in sys.argv: print('\nno verdict yet:', ' '.join(todo))

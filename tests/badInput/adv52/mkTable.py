#!/usr/bin/python3
"""mkTable.py [-t] DIR... (adv52): counts of my verdicts (verdicts.txt: "DIR PASS_ID VERDICT note", my reading of each
output; the last line for a DIR PASS_ID wins) for the outputs in out/DIR, per pass (the pass whose cases folder holds the
case) and class (OK, CRASH, HANG, SILENT, DATALOSS, UNCLEAR; "low" counted in its class; n/r apart). Written as adv51's
mkTable.py (which reads its own folder only). -t: the outputs without a verdict."""
import sys, os, glob, collections
here = os.path.dirname(os.path.abspath(__file__)); args = [a for a in sys.argv[1:] if a != '-t']
v = {}
for l in open(os.path.join(here, 'verdicts.txt')):
    f = l.split()
    if l.startswith('#') or len(f) < 3: continue
    v[(f[0], f[1])] = f[2]
C = ['OK', 'CRASH', 'HANG', 'SILENT', 'DATALOSS', 'UNCLEAR', 'n/r']
cnt = collections.defaultdict(collections.Counter); todo = []
for d in args:
    for p in sorted(glob.glob(os.path.join(here, 'out', d, '*.txt'))):
        k = os.path.basename(p)[:-4]
        if (d, k) not in v: todo.append('%s %s' % (d, k)); continue
        cnt[k.split('_')[0]][next(c for c in C if v[(d, k)].startswith(c))] += 1
print('| pass | outputs | ' + ' | '.join(C) + ' |'); print('| --- ' * (len(C) + 2) + '|')
tot = collections.Counter()
for p in sorted(cnt):
    tot.update(cnt[p]); print('| %s | %d | ' % (p, sum(cnt[p].values())) + ' | '.join(str(cnt[p][c]) for c in C) + ' |')
print('| **total** | %d | ' % sum(tot.values()) + ' | '.join(str(tot[c]) for c in C) + ' |')
if '-t' in sys.argv: print('\nno verdict yet:', ' '.join(todo))

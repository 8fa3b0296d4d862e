#!/usr/bin/python3
"""mkTable.py DIR [QUEUE]: the verdict of every earlier case's output in out/DIR (compare.py; verdicts.py's note where the
output is not simply the latest judged one's, else the latest report's verdict, latestVerdict.py). Prints counts per pass
and verdict, then one markdown row per case that is not OK or has a note."""
import sys, os, subprocess, collections
here = os.path.dirname(os.path.abspath(__file__))
exec(open(os.path.join(here, 'verdicts.py')).read())
d = sys.argv[1]
cmp = subprocess.run(['/usr/bin/python3', os.path.join(here, 'compare.py'), d], capture_output=True, text=True).stdout.splitlines()
cases = [l.split()[0] for l in cmp]
lv = subprocess.run(['/usr/bin/python3', os.path.join(here, 'latestVerdict.py')] + [x for k in cases for x in k.split('_', 1)], capture_output=True, text=True).stdout.splitlines()
latest = {'%s_%s' % tuple(l.split(' | ')[0].split()): l.split(' | ')[1] for l in lv}
cnt = collections.defaultdict(collections.Counter); rows = []; unjudged = []
for l in cmp:
    k = l.split()[0]
    if k in V: v, note = V[k]
    elif l.split()[1:3] == ['same', 'as'] and 'NOT the latest' not in l:
        lt = latest.get(k, 'OK'); v = lt.split(' [')[0].split(' (')[0].strip() + (' (low)' if '(low' in lt else ''); note = 'unchanged (%s)' % l.split('same as ')[1]
        if not v.startswith('OK'): note = 'unchanged: output equal to the latest judged one (%s); verdict there: %s' % (l.split('same as ')[1].split()[0], lt)
    else: unjudged.append(l); continue
    base = v.split(' ')[0]; cnt[k.split('_')[0]][base] += 1
    if base != 'OK' or k in V: rows.append((k, v, note))
W = ['OK', 'CRASH', 'HANG', 'SILENT', 'DATALOSS', 'UNCLEAR', 'n/r', 'see']
print('| pass | cases | ' + ' | '.join(W) + ' |'); print('|' + ' --- |' * (len(W) + 2))
tot = collections.Counter()
for p in sorted(cnt):
    print('| %s | %d | %s |' % (p, sum(cnt[p].values()), ' | '.join(str(cnt[p][w]) for w in W))); tot.update(cnt[p])
print('| **total** | %d | %s |' % (sum(tot.values()), ' | '.join(str(tot[w]) for w in W)))
print()
print('| case | verdict | observed / note |'); print('| --- | --- | --- |')
for k, v, n in rows: print('| %s | %s | %s |' % (k.replace('_', ' '), v, n))
if unjudged: print('\nUNJUDGED:\n' + '\n'.join(unjudged))

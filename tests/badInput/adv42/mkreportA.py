#!/usr/bin/python3
"""mkreportA.py [OUTDIR]: phase-A tables from queueA.txt, compareA.py and verdictsA.py: counts per pass, regressions (OK in
the latest earlier judgement, not OK now), every case not OK now. The latest earlier verdicts: adv41's report (its table)
for the cases it re-ran, else adv40's (report/verdictsA.py); only the non-OK ones are listed in EARLIER below."""
import os, subprocess, collections
here = os.path.dirname(os.path.abspath(__file__)); os.chdir(here)
EARLIER = {  # latest earlier verdict of every case that was not OK then (adv41's table; adv40's phase C for the rest)
 'adv38_x28': 'UNCLEAR', 'adv38_x55': 'UNCLEAR', 'adv38_x15': 'UNCLEAR', 'adv39_y10': 'UNCLEAR', 'adv39_y17': 'UNCLEAR',
 'adv40_z03': 'UNCLEAR', 'adv40_z05': 'UNCLEAR', 'adv37_w109': 'UNCLEAR', 'adv41_q17': 'DATALOSS'}
exec(open('verdictsA.py').read())
cases = [l.split()[:2] for l in open('queueA.txt') if l.strip() and not l.startswith('#')]
cmp = dict((l.split()[0], l) for l in subprocess.run(['/usr/bin/python3', 'compareA.py'], capture_output=True, text=True).stdout.splitlines())
V = ['OK', 'CRASH', 'HANG', 'SILENT', 'DATALOSS', 'UNCLEAR']
per = collections.OrderedDict(); rows = []
for p, i in cases:
    k = '%s_%s' % (p, i); c = cmp.get(k, '(no output)')
    if k in A: v, note = A[k]
    elif ' same as ' in c: v, note = EARLIER.get(k, 'OK'), 'output equal to an earlier judged one'
    else: v, note = '?', c
    per.setdefault(p, collections.Counter())[v] += 1; rows.append((k, EARLIER.get(k, 'OK'), v, note))
tot = collections.Counter()
print('| pass | cases | ' + ' | '.join(V) + ' |\n| --- | --- |' + ' --- |' * len(V))
for p, c in per.items():
    tot.update(c); print('| %s | %d | %s |' % (p, sum(c.values()), ' | '.join(str(c[x]) for x in V)) + (' (unjudged: %d)' % c['?'] if c['?'] else ''))
print('| **total** | %d | %s |' % (sum(tot.values()), ' | '.join(str(tot[x]) for x in V)) + (' (unjudged: %d)' % tot['?'] if tot['?'] else ''))
print('\n### Regressions (OK in the latest earlier judgement, not OK now)\n\n| case | then | now | observed now |\n| --- | --- | --- | --- |')
for k, e, v, n in rows:
    if e == 'OK' and v not in ('OK', '?'): print('| %s | %s | %s | %s |' % (k.replace('_', ' '), e, v, n))
print('\n### Not OK now (all), and verdict changes\n\n| case | then | now | observed now |\n| --- | --- | --- | --- |')
for k, e, v, n in rows:
    if v != 'OK' or e != v: print('| %s | %s | %s | %s |' % (k.replace('_', ' '), e, v, n))

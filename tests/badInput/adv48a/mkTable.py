#!/usr/bin/python3
"""mkTable.py DIR... (adv48a: adv47a's mkTable.py with my verdicts.txt; it calls adv47a's compare.py with ../../adv48a/out/DIR, which
searches the earlier passes' outputs adv35-adv46b; a later pass runs this file on its own folder: adv49a/mkTable.py): the table of adv48a's outputs in out/DIR (several DIRs: one table over them). An output's verdict:
mine in verdicts.txt ("DIR PASS_ID | VERDICT | note"), else, if compare.py finds it equal to an earlier output, the
earlier verdict: adv46a's verdictsZ.py if the equal output is adv46a's out/Z, else adv46b's verdictsP2.txt then verdictsP1.txt (adv46b cases), adv46a's verdicts.py, then adv46a's
latestVerdict.py (the latest report adv35-adv45 with a row for it). -t: also list the outputs still to judge (TODO).
Prints counts per pass and verdict, then one row per case that is not OK or has a note of mine."""
import sys, os, re, subprocess, collections
here = os.path.dirname(os.path.abspath(__file__)); bi = os.path.dirname(here); a47 = os.path.join(bi, 'adv47a')
args = [a for a in sys.argv[1:] if a != '-t']; todo = '-t' in sys.argv
mine = {}
for l in open(os.path.join(here, 'verdicts.txt')):
    if l.startswith('#') or '|' not in l: continue
    k, v, n = [x.strip() for x in l.split('|', 2)]; mine[tuple(k.split())] = (v, n)
def b46(i):
    for f in ('verdictsP2.txt', 'verdictsP1.txt'):
        for l in reversed(open(os.path.join(bi, 'adv46b', f)).read().splitlines()):
            if l.split()[:1] == [i]: return l.split()[1].replace('-low', ' (low)') + ' [adv46b %s]' % f[8:10]
V = {}; exec(open(os.path.join(bi, 'adv46a', 'verdicts.py')).read()); VZ = {}; exec(open(os.path.join(bi, 'adv46a', 'verdictsZ.py')).read())
def prior(k, src=''):
    p, i = k.split('_', 1)
    if src.startswith('adv47a:') and (src[7:], k) in mine: return mine[(src[7:], k)][0] + ' [adv47a %s]' % src[7:]
    if src == 'adv46a:Z' and k in VZ: return VZ[k][0] + ' [adv46a Z]'
    if p == 'adv46b': return b46(i) or '?'
    if k in V: return V[k][0] + ' [adv46a]'
    r = subprocess.run(['/usr/bin/python3', os.path.join(bi, 'adv46a', 'latestVerdict.py'), p, i], capture_output=True, text=True).stdout
    return r.split(' | ', 1)[1].strip() if ' | ' in r else '?'
cnt = collections.defaultdict(collections.Counter); rows = []; left = []
for d in args:
    for l in subprocess.run(['/usr/bin/python3', os.path.join(a47, 'compare.py'), '../../%s/out/%s' % (os.path.basename(here), d)], capture_output=True, text=True).stdout.splitlines():
        k = l.split()[0]
        if '(running)' in l or k.endswith(('.broken', '.firstTry')): continue
        if (d, k) in mine: v, n = mine[(d, k)]
        elif ' same as ' in ' ' + l + ' ' and 'NOT the latest' not in l:
            pv = prior(k, l.split('same as ')[1].split()[0]); v = pv.split(' [')[0].split(' (')[0].strip() + (' (low)' if '(low' in pv else ''); n = 'unchanged: %s; verdict there %s' % (l.split('same as ')[1], pv)
        else: left.append('%s %s' % (d, l)); continue
        cnt[k.split('_')[0]][v.split(' ')[0]] += 1
        if not v.startswith('OK') or (d, k) in mine: rows.append((d, k, v, n))
W = ['OK', 'CRASH', 'HANG', 'SILENT', 'DATALOSS', 'UNCLEAR']
print('| pass | cases | ' + ' | '.join(W) + ' |'); print('|' + ' --- |' * (len(W) + 2)); tot = collections.Counter()
for p in sorted(cnt):
    print('| %s | %d | %s |' % (p, sum(cnt[p].values()), ' | '.join(str(cnt[p][w]) for w in W))); tot.update(cnt[p])
print('| **total** | %d | %s |' % (sum(tot.values()), ' | '.join(str(tot[w]) for w in W)))
print('\n| out | case | verdict | what happened |\n| --- | --- | --- | --- |')
for d, k, v, n in rows: print('| %s | %s | %s | %s |' % (d, k.replace('_', ' '), v, n))
if left and todo: print('\nTODO (not judged yet):\n' + '\n'.join(left))

#!/usr/bin/python3
"""compareM.py [KEY...]: each phase-M output (out/M/PASS_ID.txt) against adv40's phase-C output of the same case
(adv40/out/C, else adv40/out/A), normalised with adv40's compareA.py norm (case folders, pids, dates, durations);
prints same/DIFF and the diff."""
import sys, os, glob, difflib
here = os.path.dirname(os.path.abspath(__file__)); a40 = os.path.join(here, '..', 'adv40')
src = open(os.path.join(a40, 'compareA.py')).read().split('verbose = ')[0]
ns = {'__file__': os.path.join(a40, 'compareA.py')}; exec(src, ns); norm = ns['norm']
files = ['%s/out/M/%s.txt' % (here, a) for a in sys.argv[1:]] if sys.argv[1:] else sorted(glob.glob('%s/out/M/*.txt' % here))
for f in files:
    k = os.path.basename(f)[:-4]
    cands = [p for p in ('%s/out/%s/%s.txt' % (a40, x, k) for x in ('A', 'C')) if os.path.exists(p)]
    if not cands: print(k, '(no adv40 output)'); continue
    old = norm(open(cands[-1], errors='replace').read().replace('adv40C-', 'adv40-')); new = norm(open(f, errors='replace').read().replace('adv41M-', 'adv40-'))
    if old == new: print(k, 'same'); continue
    print(k, 'DIFF against', os.path.relpath(cands[-1], a40))
    for l in difflib.unified_diff(old.splitlines(), new.splitlines(), 'before', 'now', n=0, lineterm=''):
        if not l.startswith(('---', '+++', '@@')): print('    ' + l[:330])

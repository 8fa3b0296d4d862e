#!/usr/bin/python3
"""compareC.py [-v] [PASS_ID...]: each phase-C output (out/C/PASS_ID.txt, the merge of fix19w) against this pass's own
output of the same case before the merge (out/A, else the latest of out/B, B2, B3, preC), after adv40's normalisation
(compareA.py's n). Prints same/DIFF; -v: the diff."""
import sys, os, glob, difflib
here = os.path.dirname(os.path.abspath(__file__))
src = open(os.path.join(here, 'compareA.py')).read().split('\nverbose = ')[0]
ns = {'__file__': os.path.join(here, 'compareA.py')}; exec(src, ns); n, same = ns['n'], ns['same']
verbose = '-v' in sys.argv; args = [a for a in sys.argv[1:] if a != '-v']
files = ['%s/out/C/%s.txt' % (here, a) for a in args] if args else sorted(glob.glob(here + '/out/C/*.txt'))
for f in files:
    k = os.path.basename(f)[:-4]; raw = open(f, errors='replace').read().replace('/tmp/adv42C-', '/tmp/adv42-')
    if '[case exit' not in raw: print(k, '(running)'); continue
    c = [p for p in ('%s/out/%s/%s.txt' % (here, d, k) for d in ('A', 'B', 'B2', 'B3', 'B4', 'B5', 'B6', 'B7', 'preC')) if os.path.exists(p)]
    if not c: print(k, '(no earlier output)'); continue
    old = n(open(c[-1], errors='replace').read()); now = n(raw)
    print(k, 'same as' if same(old, now) else 'DIFF against', os.path.relpath(c[-1], here))
    if verbose and not same(old, now):
        for l in difflib.unified_diff(old.splitlines(), now.splitlines(), 'before', 'now', n=0, lineterm=''):
            if not l.startswith(('---', '+++', '@@')): print('    ' + l[:330])

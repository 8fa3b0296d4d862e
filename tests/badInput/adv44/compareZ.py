#!/usr/bin/python3
"""compareZ.py [-v] DIR [PASS_ID...]: each output of out/DIR (phase 2) against this pass's own phase-1 output of the same
case (out/P1, P1b, R, A, A2, A3, A4, A5), normalised as compare.py; "same as phase 1 (X)" or DIFF; -v: the diff."""
import sys, os, glob, difflib
here = os.path.dirname(os.path.abspath(__file__))
exec(open(os.path.join(here, 'compare.py')).read().split("if __name__")[0])
verbose = '-v' in sys.argv; args = [a for a in sys.argv[1:] if a != '-v']; d = args.pop(0)
files = ['%s/out/%s/%s.txt' % (here, d, a) for a in args] if args else sorted(glob.glob('%s/out/%s/*.txt' % (here, d)))
for f in files:
    k = os.path.basename(f)[:-4]; now = n(open(f, errors='replace').read())
    for p in ('Z', 'A5', 'A3', 'A4', 'A2', 'A', 'P1b', 'P1', 'R', 'ZR'):
        g = os.path.join(here, 'out', p, k + '.txt')
        if os.path.exists(g): break
    else: print(k, '(no phase-1 output)'); continue
    old = n(open(g, errors='replace').read())
    if same(old, now): print(k, 'same as phase 1 (%s)' % p); continue
    print(k, 'DIFF against phase 1 (%s)' % p)
    if verbose:
        for l in difflib.unified_diff(old.splitlines(), now.splitlines(), 'before', 'now', n=0, lineterm=''):
            if not l.startswith(('---', '+++', '@@')): print('    ' + l[:300])

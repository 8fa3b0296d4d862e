#!/usr/bin/python3
"""compareC.py [-d DIR] [KEY...]: each phase-C output (out/DIR/PASS_ID.txt, DIR default C) against the same case's
phase-A/B output on 79a71b4 (out/A, or for adv40's own cases the last of out/B, out/B3, out/B4), normalised as
compareA.py does; prints same/DIFF and the diff."""
import sys, os, glob, difflib
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import importlib.util
spec = importlib.util.spec_from_file_location('cA', os.path.join(os.path.dirname(os.path.abspath(__file__)), 'compareA.py'))
here = os.path.dirname(os.path.abspath(__file__))
src = open(os.path.join(here, 'compareA.py')).read().split('verbose = ')[0]
ns = {'__file__': os.path.join(here, 'compareA.py')}; exec(src, ns); norm = ns['norm']
args = sys.argv[1:]; d = 'C'
if args[:1] == ['-d']: d = args[1]; args = args[2:]
files = ['%s/out/%s/%s.txt' % (here, d, a) for a in args] if args else sorted(glob.glob('%s/out/%s/*.txt' % (here, d)))
for f in files:
    k = os.path.basename(f)[:-4]
    if k.startswith('adv40_'):
        cands = [p for p in ('%s/out/%s/%s.txt' % (here, x, k) for x in ('B', 'B3', 'B4')) if os.path.exists(p)]
    else:
        cands = [p for p in ['%s/out/A/%s.txt' % (here, k)] if os.path.exists(p)]
    if not cands: print(k, '(no phase A/B output)'); continue
    old = norm(open(cands[-1], errors='replace').read()); new = norm(open(f, errors='replace').read())
    if old == new: print(k, 'same'); continue
    print(k, 'DIFF against', os.path.relpath(cands[-1], here))
    for l in difflib.unified_diff(old.splitlines(), new.splitlines(), 'before', 'now', n=0, lineterm=''):
        if not l.startswith(('---', '+++', '@@')): print('    ' + l[:330])

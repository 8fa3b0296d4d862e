#!/usr/bin/python3
"""compare.py [-v] DIR [PASS_ID...]: adv46a's compare.py (imported, its normalisation and search unchanged) for adv47a's
outputs out/DIR/PASS_ID.txt, with adv46a's and adv46b's outputs first among the earlier ones (latest first: adv46a out/Z,
E, N, B; adv46b out/P2g, P2f, P2e, P2d, P2c, P2b, P2a, P1c, P1b, P1; then adv46a's list: adv45 ... adv40). Prints per
case (phase 2, DIR Z: my phase-1 outputs out/Q2, Q1c, Q1x, Q1 first) the earlier outputs it equals (adv46b's ik base's 10 force rows read as this pass's 20) ("same as ...", the latest first) or DIFF (against the latest found); -v: the diff."""
import sys, os, glob, difflib, importlib.util
here = os.path.dirname(os.path.abspath(__file__)); bi = os.path.dirname(here)
spec = importlib.util.spec_from_file_location('cmp46a', os.path.join(bi, 'adv46a', 'compare.py')); c = importlib.util.module_from_spec(spec); spec.loader.exec_module(c)
c.DIRS = [('adv46a', d) for d in ('Z', 'E', 'N', 'B')] + [('adv46b', d) for d in ('P2g', 'P2f', 'P2e', 'P2d', 'P2c', 'P2b', 'P2a', 'P1c', 'P1b', 'P1')] + c.DIRS
import re
same = c.same
def n(t):
    """adv46a's normalisation, plus the process id in bash's 'Floating point exception' line"""
    return c.n(re.sub(r'line \d+: \d+ Floating point exception', 'line L: N Floating point exception', t))
def earlier(k):
    """adv46a's, with adv46b's ik base (killed 1 s after its first checkpoint) taken as it is in this pass: 20 force rows at
    the kill where adv46b's had 10 ('force.dat 10 rows' and 'row 1, step 10' read as 20 in the earlier outputs)"""
    return [(b, t.replace('force.dat 10 rows', 'force.dat 20 rows').replace('row 1, step 10', 'row 1, step 20')) for b, t in c.earlier(k)]
if __name__ == '__main__':
    verbose = '-v' in sys.argv; args = [a for a in sys.argv[1:] if a != '-v']; d = args.pop(0)
    if d.startswith('Z'): c.DIRS = [('adv47a', x) for x in ('Q2', 'Q1c', 'Q1x', 'Q1')] + c.DIRS   # phase 2: my phase-1 outputs first
    files = ['%s/out/%s/%s.txt' % (here, d, a) for a in args] if args else sorted(glob.glob('%s/out/%s/*.txt' % (here, d)))
    for f in files:
        k = os.path.basename(f)[:-4]; raw = open(f, errors='replace').read()
        if '[case exit' not in raw: print(k, '(running)'); continue
        now = n(raw); bs = [(b, n(t)) for b, t in earlier(k)]
        eq = [b for b, t in bs if same(t, now)]
        late = '' if not eq or eq[0] == bs[0][0] else ' (NOT the latest: differs from %s)' % bs[0][0]
        print(k, ('same as ' + ' '.join(eq[:3]) + late) if eq else ('DIFF against ' + bs[0][0] if bs else '(no earlier output)'))
        if verbose and bs and (not eq or late):
            for l in difflib.unified_diff(bs[0][1].splitlines(), now.splitlines(), 'before', 'now', n=0, lineterm=''):
                if not l.startswith(('---', '+++', '@@')): print('    ' + l[:330])

#!/usr/bin/python3
"""compare.py [-v] DIR [PASS_ID...] (adv50a): adv49a's compare.py (imported: adv47a's and adv46a's normalisation and
search) for my outputs out/DIR/PASS_ID.txt, with my base prefix /tmp/adv50a- made the earlier passes' one (adv46a's
normalisation knows /tmp/adv4N*- only) and the outputs of adv49a (out/P2, J, G, Z, Q2, Q5) and adv49b (out/P2d, P2c, P2b,
P2a, P1b, P1) first among the earlier ones. Prints per case the earlier outputs it equals ("same as ...") or DIFF
(against the latest found); -v: the diff. Written because adv49a's list stops at adv48a/adv48b."""
import sys, os, re, glob, difflib, importlib.util
here = os.path.dirname(os.path.abspath(__file__)); bi = os.path.dirname(here)
spec = importlib.util.spec_from_file_location('cmp49a', os.path.join(bi, 'adv49a', 'compare.py')); m = importlib.util.module_from_spec(spec); spec.loader.exec_module(m)
c = m.c   # adv47a's module (its .c is adv46a's, whose DIRS adv49a set)
c.c.DIRS = [('adv49a', d) for d in ('P2', 'J', 'G', 'Z', 'Q2', 'Q5')] + [('adv49b', d) for d in ('P2d', 'P2c', 'P2b', 'P2a', 'P1b', 'P1')] + c.c.DIRS
def n(t):
    return c.n(re.sub(r'/tmp/adv50a-', '/tmp/adv49a-', t))
if __name__ == '__main__':
    verbose = '-v' in sys.argv; args = [a for a in sys.argv[1:] if a != '-v']; d = args.pop(0)
    files = ['%s/out/%s/%s.txt' % (here, d, a) for a in args] if args else sorted(glob.glob('%s/out/%s/*.txt' % (here, d)))
    for f in files:
        k = os.path.basename(f)[:-4]; raw = open(f, errors='replace').read()
        if '[case exit' not in raw: print(k, '(running)'); continue
        now = n(raw); bs = [(b, n(t)) for b, t in c.earlier(k)]
        eq = [b for b, t in bs if c.same(t, now)]
        late = '' if not eq or eq[0] == bs[0][0] else ' (NOT the latest: differs from %s)' % bs[0][0]
        print(k, ('same as ' + ' '.join(eq[:3]) + late) if eq else ('DIFF against ' + bs[0][0] if bs else '(no earlier output)'))
        if verbose and bs and (not eq or late):
            for l in difflib.unified_diff(bs[0][1].splitlines(), now.splitlines(), 'before', 'now', n=0, lineterm=''):
                if not l.startswith(('---', '+++', '@@')): print('    ' + l[:330])

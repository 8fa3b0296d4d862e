#!/usr/bin/python3
"""compare.py [-v] DIR [PASS_ID...] (adv49a): adv47a's compare.py (imported: adv46a's normalisation and search) for my outputs
out/DIR/PASS_ID.txt, with the outputs of adv48a, adv48b, adv47b and adv47a first among the earlier ones (latest first: adv48a
out/lead43, Q3m, Q5, Za, Q4, Q3, P1; adv48b out/lead43, P2b, P2a, P1i ... P1; adv47b out/lead42, P2a, P1f ... P1; adv47a
out/lead42, Z, Q3, Q2, Q1c, Q1x, Q1), then adv47a's list. Prints per case the earlier outputs it equals ("same as ...") or
DIFF (against the latest found); -v: the diff. Written because adv47a's list stops at adv46b."""
import sys, os, glob, difflib, importlib.util
here = os.path.dirname(os.path.abspath(__file__)); bi = os.path.dirname(here)
spec = importlib.util.spec_from_file_location('cmp47a', os.path.join(bi, 'adv47a', 'compare.py')); c = importlib.util.module_from_spec(spec); spec.loader.exec_module(c)
c.c.DIRS = [('adv48a', d) for d in ('lead43', 'Q3m', 'Q5', 'Za', 'Q4', 'Q3', 'P1')] + \
    [('adv48b', d) for d in ('lead43', 'P2b', 'P2a', 'P1i', 'P1h', 'P1g', 'P1f', 'P1e', 'P1d', 'P1c', 'P1b', 'P1')] + \
    [('adv47b', d) for d in ('lead42', 'P2a', 'P1f', 'P1e', 'P1d', 'P1c', 'P1b', 'P1')] + \
    [('adv47a', d) for d in ('lead42', 'Z', 'Q3', 'Q2', 'Q1c', 'Q1x', 'Q1')] + c.c.DIRS
if __name__ == '__main__':
    verbose = '-v' in sys.argv; args = [a for a in sys.argv[1:] if a != '-v']; d = args.pop(0)
    files = ['%s/out/%s/%s.txt' % (here, d, a) for a in args] if args else sorted(glob.glob('%s/out/%s/*.txt' % (here, d)))
    for f in files:
        k = os.path.basename(f)[:-4]; raw = open(f, errors='replace').read()
        if '[case exit' not in raw: print(k, '(running)'); continue
        now = c.n(raw); bs = [(b, c.n(t)) for b, t in c.earlier(k)]
        eq = [b for b, t in bs if c.same(t, now)]
        late = '' if not eq or eq[0] == bs[0][0] else ' (NOT the latest: differs from %s)' % bs[0][0]
        print(k, ('same as ' + ' '.join(eq[:3]) + late) if eq else ('DIFF against ' + bs[0][0] if bs else '(no earlier output)'))
        if verbose and bs and (not eq or late):
            for l in difflib.unified_diff(bs[0][1].splitlines(), now.splitlines(), 'before', 'now', n=0, lineterm=''):
                if not l.startswith(('---', '+++', '@@')): print('    ' + l[:330])

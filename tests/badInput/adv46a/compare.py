#!/usr/bin/python3
"""compare.py [-v] DIR [PASS_ID...]: (adv45's, with adv45's outputs first) each adv46a output out/DIR/PASS_ID.txt against the earlier outputs of the same case
committed in this tree (latest first: adv45 out/Z2, Z1, Z, N, B; adv44 out/lead39, Z2, Z, ZR, A5..A, P1b, P1, R; adv43 out/F4, F3, F2, F, preA, preN, pre2, pre; adv42 out/C2, C, preC, B7..B2, B, A;
adv41 out/M, pre; adv40 out/C, B4, B3, B2, B, A2, A), after adv43's normalisation (adv40/compareA.py norm: case folders,
pids, dates, durations; base-case prefixes made one). Prints per case the earlier outputs it equals ("same as ...", the
latest first) or DIFF (against the latest found); -v: the diff."""
import sys, os, re, glob, difflib
here = os.path.dirname(os.path.abspath(__file__)); bi = os.path.dirname(here)
src = open(os.path.join(bi, 'adv40', 'compareA.py')).read().split('verbose = ')[0]
ns = {'__file__': os.path.join(bi, 'adv40', 'compareA.py')}; exec(src, ns); norm, same = ns['norm'], ns['same']
def n(t):
    t = re.sub(r'/tmp/adv4[0-9][A-Za-z]*-', '/tmp/adv40-', t)
    t = re.sub(r'/work/wt-adv[0-9a-z]+', '/work/wt', t)
    t = re.sub(r'/work/wt/adv[0-9a-z]+', '/work/wt', t)
    return wall(norm(t))
def wall(t):
    """adv46a: the last cell of sweepCase's tables whose last header is 'wall [s]' (a duration) made 'x'"""
    out, inw = [], False
    for l in t.split('\n'):
        if l.rstrip().endswith('wall [s] |'): inw = True
        elif inw and l.startswith('|') and not l.startswith('|---'): l = re.sub(r'\| *[0-9.]+ *\|\s*$', '| x |', l)
        elif not l.startswith('|'): inw = False
        out.append(l)
    return '\n'.join(out)
DIRS = [('adv45', d) for d in ('Z2', 'Z1', 'Z', 'N', 'B')] + [('adv44', d) for d in ('lead39', 'Z2', 'Z', 'ZR', 'A5', 'A4', 'A3', 'A2', 'A', 'P1b', 'P1', 'R')] + \
       [('adv43', d) for d in ('F4', 'F3', 'F2', 'F', 'preA', 'preN', 'pre2', 'pre')] + \
       [('adv42', d) for d in ('C2', 'C', 'preC', 'B7', 'B6', 'B5', 'B4', 'B3', 'B2', 'B', 'A')] + \
       [('adv41', d) for d in ('M', 'pre')] + [('adv40', d) for d in ('C', 'B4', 'B3', 'B2', 'B', 'A2', 'A')]
def earlier(k):
    out = []
    for p, d in DIRS:
        f = os.path.join(bi, p, 'out', d, k + '.txt')
        if not os.path.exists(f) and p == 'adv40': f = os.path.join(bi, p, 'out', d, k.split('_', 1)[1] + '.txt') if k.startswith('adv40_') else f
        if os.path.exists(f): out.append(('%s:%s' % (p, d), open(f, errors='replace').read()))
    return out
if __name__ == '__main__':
    verbose = '-v' in sys.argv; args = [a for a in sys.argv[1:] if a != '-v']; d = args.pop(0)
    files = ['%s/out/%s/%s.txt' % (here, d, a) for a in args] if args else sorted(glob.glob('%s/out/%s/*.txt' % (here, d)))
    for f in files:
        k = os.path.basename(f)[:-4]; raw = open(f, errors='replace').read()
        if '[case exit' not in raw: print(k, '(running)'); continue
        now = n(raw); bs = earlier(k)
        eq = [b for b, t in bs if same(n(t), now)]
        late = '' if not eq or eq[0] == bs[0][0] else ' (NOT the latest: differs from %s)' % bs[0][0]
        print(k, ('same as ' + ' '.join(eq[:3]) + late) if eq else ('DIFF against ' + bs[0][0] if bs else '(no earlier output)'))
        if verbose and bs and (not eq or late):
            for l in difflib.unified_diff(n(bs[0][1]).splitlines(), now.splitlines(), 'before', 'now', n=0, lineterm=''):
                if not l.startswith(('---', '+++', '@@')): print('    ' + l[:330])

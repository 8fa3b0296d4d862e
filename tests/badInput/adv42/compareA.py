#!/usr/bin/python3
"""compareA.py [-v] [PASS_ID...]: each adv42 phase-A output (out/A/PASS_ID.txt) against the earlier outputs of the same
case by adv40 and adv41 (adv40 out/A, A2, B, B3, B4, C; adv41 out/pre, M), after adv40's normalisation (compareA.py norm:
case folders, pids, dates, durations; the base-case prefixes adv40C-, adv41M-, adv42- made one). Prints per case the
earlier outputs it equals ("same as ...") or DIFF (against the newest one); -v: the diff."""
import sys, os, re, glob, difflib
here = os.path.dirname(os.path.abspath(__file__)); bi = os.path.dirname(here); a40 = os.path.join(bi, 'adv40'); a41 = os.path.join(bi, 'adv41')
src = open(os.path.join(a40, 'compareA.py')).read().split('verbose = ')[0]
ns = {'__file__': os.path.join(a40, 'compareA.py')}; exec(src, ns); norm, same = ns['norm'], ns['same']
def n(t):
    for p in ('adv40C-', 'adv41M-', 'adv42-', 'adv40-B', 'adv41-'): t = t.replace('/tmp/' + p, '/tmp/adv40-')
    t = re.sub(r'/work/wt-adv[0-9a-z]+', '/work/wt', t)
    return norm(t)
def earlier(k):
    c = ['%s/out/%s/%s.txt' % (a40, d, k) for d in ('A', 'A2', 'B', 'B3', 'B4', 'C')] + ['%s/out/%s/%s.txt' % (a41, d, k) for d in ('pre', 'M')]
    return [p for p in c if os.path.exists(p)]
verbose = '-v' in sys.argv; args = [a for a in sys.argv[1:] if a != '-v']; d = os.environ.get('OUTDIR', 'A')
files = ['%s/out/%s/%s.txt' % (here, d, a) for a in args] if args else sorted(glob.glob('%s/out/%s/*.txt' % (here, d)))
for f in files:
    k = os.path.basename(f)[:-4]; raw = open(f, errors='replace').read()
    if '[case exit' not in raw: print(k, '(running)'); continue
    now = n(raw); bs = earlier(k)
    eq = [os.path.relpath(b, bi).replace('/out/', ':').replace('.txt', '').rsplit('/', 1)[0] for b in bs if same(n(open(b, errors='replace').read()), now)]
    print(k, ('same as ' + ' '.join(eq)) if eq else ('DIFF against ' + os.path.relpath(bs[-1], bi) if bs else '(no earlier output)'))
    if verbose and bs and not eq:
        for l in difflib.unified_diff(n(open(bs[-1], errors='replace').read()).splitlines(), now.splitlines(), 'before', 'now', n=0, lineterm=''):
            if not l.startswith(('---', '+++', '@@')): print('    ' + l[:330])

#!/usr/bin/python3
"""compare.py [-v] DIR [PASS_ID...]: each adv43 output out/DIR/PASS_ID.txt against adv42's outputs of the same case
(branch adv42 74e63eb, read from /work/wt-adv42 or git show adv42:...: out/A, B..B7, preC), after adv40's normalisation
(adv40/compareA.py norm: case folders, pids, dates, durations; base-case prefixes made one). Prints per case the adv42
outputs it equals ("same as ...") or DIFF (against the last found); -v: the diff."""
import sys, os, re, glob, difflib, subprocess
here = os.path.dirname(os.path.abspath(__file__)); bi = os.path.dirname(here)
src = open(os.path.join(bi, 'adv40', 'compareA.py')).read().split('verbose = ')[0]
ns = {'__file__': os.path.join(bi, 'adv40', 'compareA.py')}; exec(src, ns); norm, same = ns['norm'], ns['same']
def n(t):
    t = re.sub(r'/tmp/adv4[0-9][A-Za-z]*-', '/tmp/adv40-', t)
    t = re.sub(r'/work/wt-adv[0-9a-z]+', '/work/wt', t)
    return norm(t)
def earlier(k):
    out = []
    for d in ('A', 'B', 'B2', 'B3', 'B4', 'B5', 'B6', 'B7', 'preC'):
        try: out.append((d, subprocess.run(['git', '-C', here, 'show', 'adv42:tests/badInput/adv42/out/%s/%s.txt' % (d, k)], capture_output=True, text=True, errors='replace', check=True).stdout))
        except subprocess.CalledProcessError: pass
    return out
verbose = '-v' in sys.argv; args = [a for a in sys.argv[1:] if a != '-v']; d = args.pop(0)
files = ['%s/out/%s/%s.txt' % (here, d, a) for a in args] if args else sorted(glob.glob('%s/out/%s/*.txt' % (here, d)))
for f in files:
    k = os.path.basename(f)[:-4]; raw = open(f, errors='replace').read()
    if '[case exit' not in raw: print(k, '(running)'); continue
    now = n(raw); bs = earlier(k)
    eq = ['adv42:' + b for b, t in bs if same(n(t), now)]
    print(k, ('same as ' + ' '.join(eq)) if eq else ('DIFF against adv42:' + bs[-1][0] if bs else '(no earlier output)'))
    if verbose and bs and not eq:
        for l in difflib.unified_diff(n(bs[-1][1]).splitlines(), now.splitlines(), 'before', 'now', n=0, lineterm=''):
            if not l.startswith(('---', '+++', '@@')): print('    ' + l[:330])

#!/usr/bin/python3
"""compareA.py [PASS_ID...]: each phase-A output (out/A/PASS_ID.txt) against the earlier outputs of the same reproducer
(the pass's own out/new, and the later re-runs: adv36 out/rerun, adv37 out/p2 (adv36_*), adv38 out/p2 (adv37_*) and
out/p3, adv35's notes copy), after normalising what differs between runs by nature (case folders, process ids, host,
dates, durations, random kill delays). Prints per case: same/DIFF against each baseline; -v: the diff against the last."""
import sys, os, re, glob, difflib
here = os.path.dirname(os.path.abspath(__file__)); bi = os.path.dirname(here)
def norm(t):
    t = re.sub(r'/tmp/[A-Za-z0-9_.+-]+/w\.[A-Za-z0-9]{6}', 'W', t)
    t = re.sub(r'/tmp/adv[0-9a-z_-]+', 'ADV', t)
    t = re.sub(r'\[case exit (\d+), [0-9.]+ s\]', r'[case exit \1]', t)
    t = re.sub(r'\b(process|pid|processes|PID|Process)( id)?[ :=]+\d+', r'\1 N', t)
    t = re.sub(r'\d{4}-\d\d-\d\dT\d\d:\d\d:\d\d(\.\d+)?', 'DATE', t)
    t = re.sub(r'\(\+[0-9.]+ s\)', '(+x s)', t)
    t = re.sub(r'\b\d+\.\d+ s\b', 'x s', t)
    t = re.sub(r'host [A-Za-z0-9_.-]+', 'host H', t)
    t = re.sub(r'\b\d{3,7}:', 'N:', t)
    t = re.sub(r'at line \d+', 'at line L', t)
    t = re.sub(r'(\[\d\] )? *From function .*', 'FROM', t)
    t = re.sub(r'from line \d+ to line \d+', 'from line A to line B', t)
    t = re.sub(r'line \d+: +\d+ (Killed|Terminated)', r'line L: N \1', t)
    t = re.sub(r'\[left running after the case, SIGKILLed: [0-9 ]*\]\n', '', t)
    t = re.sub(r' log\.[A-Za-z.]+\.status', '', t)
    t = re.sub(r'sweep_s\d+', 'sweep_sN', t)
    t = re.sub(r'[A-Z][a-z]{2} +\d+ \d\d:\d\d', 'MTIME', t)
    t = re.sub(r'\b\d\d:\d\d:\d\d\b', 'HMS', t)
    t = re.sub(r'(already run on \S+)( \(it ended: exit status \d+, \S+\))?: remove log( file)? .(log\.\S+?). to (re-run|run it again)', r'\1: remove \4', t)
    return t
def same(a, b):
    """equal, line by line, up to where the shorter of two long lines was cut by the case (at a fixed width, before
    the case folder's name was shortened here)"""
    a, b = a.splitlines(), b.splitlines()
    if len(a) != len(b): return False
    for x, y in zip(a, b):
        if x != y and not (min(len(x), len(y)) >= 100 and (x.startswith(y) or y.startswith(x) or x[:min(len(x), len(y)) - 12] == y[:min(len(x), len(y)) - 12])):
            return False
    return True
def base(pass_, id_):
    c = []
    if pass_ == 'adv35':
        c += ['/work/notes/adv35/out/%s.txt' % id_, bi + '/adv35/out/%s.txt' % id_, bi + '/adv36/out/rerun/%s.txt' % id_]
    elif pass_ == 'adv36':
        c += [bi + '/adv36/out/new/%s.txt' % id_, bi + '/adv37/out/p2/adv36_%s.txt' % id_, bi + '/adv38/out/p2/adv36_%s.txt' % id_]
    elif pass_ == 'adv37':
        c += [bi + '/adv37/out/new/%s.txt' % id_, bi + '/adv37/out/p2/%s.txt' % id_, bi + '/adv38/out/p2/adv37_%s.txt' % id_, bi + '/adv38/out/p3/adv37_%s.txt' % id_]
    elif pass_ == 'adv38':
        c += [bi + '/adv38/out/new/%s.txt' % id_, bi + '/adv38/out/p2/%s.txt' % id_, bi + '/adv38/out/p3/%s.txt' % id_]
    elif pass_ == 'adv39':
        c += [bi + '/adv39/out/new/%s.txt' % id_]
    return [p for p in c if os.path.exists(p)]
verbose = '-v' in sys.argv; args = [a for a in sys.argv[1:] if a != '-v']
files = ['%s/out/A/%s.txt' % (here, a) for a in args] if args else sorted(glob.glob(here + '/out/A/*.txt'))
for f in files:
    k = os.path.basename(f)[:-4]; p, i = k.split('_', 1)
    raw = open(f, errors='replace').read()
    if '[case exit' not in raw: print(k, '(running)'); continue
    now = norm(raw); bs = base(p, i)
    res = []
    for b in bs:
        old = norm(open(b, errors='replace').read())
        res.append('%s:%s' % (os.path.relpath(b, bi).replace('/out/', ':').replace('.txt', ''), 'same' if same(old, now) else 'DIFF'))
    print(k, ' '.join(res) if res else '(no earlier output)')
    if verbose and bs:
        old = norm(open(bs[-1], errors='replace').read())
        for l in difflib.unified_diff(old.splitlines(), now.splitlines(), 'before', 'now', n=0, lineterm=''):
            print('    ' + l[:300])

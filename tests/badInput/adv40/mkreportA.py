#!/usr/bin/python3
"""mkreportA.py: the phase-A tables of report.md from verdictsA.py, the earlier passes' verdicts and compareA.py's
comparison of out/A with the earlier outputs. Prints markdown."""
import sys, os, re, importlib, subprocess, collections
here = os.path.dirname(os.path.abspath(__file__)); bi = os.path.dirname(here); sys.path.insert(0, here)
import verdictsA
def load(p):
    sys.path.insert(0, os.path.join(bi, p)); m = importlib.import_module('verdicts'); sys.path.pop(0); del sys.modules['verdicts']; return m
orig, later = {}, {}
v = load('adv35')
for k, x in v.V.items(): orig['adv35_' + k] = x[1]
for k, x in load('adv36').RERUN.items(): later['adv35_' + k] = ('adv36 re-run', x[1])
for p in ('adv36', 'adv37', 'adv38'):
    m = load(p)
    for k, x in m.NEW.items(): orig['%s_%s' % (p, k)] = x[1]
    for k, x in getattr(m, 'P2', {}).items():
        key = k.replace(':', '_') if ':' in k else '%s_%s' % (p, k)
        if key not in orig: orig[key] = x[1]
        else: later[key] = ('%s phase 2' % p, x[1])
hdr = {}
for p in ('adv35', 'adv36', 'adv37', 'adv38', 'adv39'):
    for f in os.listdir(os.path.join(bi, p, 'cases')):
        t = open(os.path.join(bi, p, 'cases', f)).read().splitlines()
        h = [l for l in t[:3] if re.match(r'# [a-z]\d+:', l)]
        hdr['%s_%s' % (p, f[:-3])] = h[0].split(':', 1)[1].strip() if h else ''
for line in open(os.path.join(bi, 'adv39', 'report.md')):
    m = re.match(r'\| ([wxy]\d+) \|.*\| ([A-Za-z/ ]+?)(?: \(.*\))? \|\s*$', line)
    if not m: continue
    k = m.group(1); vv = m.group(2).strip()
    if k.startswith('y'): orig['adv39_' + k] = vv
    else:
        key = ('adv37_' if k.startswith('w') else 'adv38_') + k
        later[key] = ('adv39 phase A', vv)
for k in hdr:
    orig.setdefault(k, 'OK')
now = {k: verdictsA.A.get(k, ('OK', ''))[0] for k in hdr}
cnt = collections.Counter(now.values())
print('Phase A: %d cases re-run; verdicts now: %s' % (len(hdr), ', '.join('%s %d' % (x, cnt[x]) for x in ('OK', 'CRASH', 'HANG', 'SILENT', 'DATALOSS', 'UNCLEAR'))))
print()
print('Per pass:')
print()
print('| pass | cases | OK | CRASH | HANG | SILENT | DATALOSS | UNCLEAR |')
print('| --- | --- | --- | --- | --- | --- | --- | --- |')
for p in ('adv35', 'adv36', 'adv37', 'adv38', 'adv39'):
    ks = [k for k in hdr if k.startswith(p)]; c = collections.Counter(now[k] for k in ks)
    print('| %s | %d | %s |' % (p, len(ks), ' | '.join(str(c[x]) for x in ('OK', 'CRASH', 'HANG', 'SILENT', 'DATALOSS', 'UNCLEAR'))))
print()
def row(k, note):
    p, i = k.split('_', 1)
    lt = later.get(k); lts = '%s: %s' % lt if lt else ''
    return '| %s %s | %s | %s | %s | %s | %s |' % (p, i, hdr[k][:150].replace('|', '/'), orig[k], lts, now[k], note.replace('|', '/'))
print('### Regressions (OK in the pass that made the case, or in its latest re-check, and not OK now)')
print()
print('| case | what | verdict then | later re-check | now | observed now |')
print('| --- | --- | --- | --- | --- | --- |')
for k in sorted(hdr):
    last = later.get(k, (None, orig[k]))[1]
    if now[k] != 'OK' and (orig[k] == 'OK' or last.startswith('OK')):
        print(row(k, verdictsA.A[k][1]))
print()
print('### Not OK now (all)')
print()
print('| case | what | verdict then | later re-check | now | observed now |')
print('| --- | --- | --- | --- | --- | --- |')
for k in sorted(hdr):
    if now[k] != 'OK': print(row(k, verdictsA.A[k][1]))
print()
print('### Not OK in the pass that made them, OK now')
print()
print('| case | what | verdict then | later re-check | now | output now |')
print('| --- | --- | --- | --- | --- | --- |')
for k in sorted(hdr):
    if orig[k] != 'OK' and now[k] == 'OK':
        cmp = subprocess.run([os.path.join(here, 'compareA.py'), k], capture_output=True, text=True).stdout.split(None, 1)[1].strip()
        same = [c.rsplit(':', 1)[0] for c in cmp.split() if c.endswith(':same')]
        note = verdictsA.A.get(k, ('OK', ''))[1] or ('as %s' % same[-1].replace('../../../notes/', 'notes/') if same else 'reviewed (the output differs from every earlier one; see out/A)')
        print(row(k, note))

#!/usr/bin/python3
"""mkreport.py: the table of report.md from verdicts.py, the cases' headers and out/<rerun|new>/<id>.txt"""
import os, re, sys
here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, here)
from verdicts import RERUN, NEW

def header(path):
    with open(path) as f:
        lines = f.read().splitlines()
    return re.sub(r'^# *\w+: *', '', lines[1]) if len(lines) > 1 else ''

def observed(path, n=4, width=330):
    if not os.path.exists(path):
        return '(not run)'
    with open(path, errors='replace') as f:
        lines = [l.strip() for l in f.read().splitlines()]
    keep = [l for l in lines if l and not l.startswith('From function') and not l.startswith('in file')
            and l != 'FOAM exiting' and not l.startswith('[case exit')]
    tail = [l for l in lines if l.startswith('[case exit')]
    s = ' / '.join(keep[:n])
    if len(s) > width:
        s = s[:width] + ' ...'
    s += ' ' + (tail[-1] if tail else '')
    return s.replace('|', '\\|')

def table(d, casesDir, outDir):
    rows = ['| id | class | input | observed (first lines, [case exit, time]) | verdict |', '|---|---|---|---|---|']
    for k in sorted(d):
        cls, v, why = d[k]
        inp = header(os.path.join(casesDir, k + '.sh')).replace('|', '\\|')
        obs = observed(os.path.join(here, 'out', outDir, k + '.txt'))
        verdict = '**%s**' % v if v == 'OK' else '**%s**: %s' % (v, why.replace('|', '\\|'))
        if v == 'OK':
            verdict += ': ' + why.replace('|', '\\|')
        rows.append('| %s | %s | %s | %s | %s |' % (k, cls, inp, obs, verdict))
    return '\n'.join(rows)

def counts(d):
    c = {}
    for k, (cls, v, why) in d.items():
        c.setdefault(v, []).append(k)
    return c

out = []
for name, d in (('rerun', RERUN), ('new', NEW)):
    c = counts(d)
    out.append('%s: %d cases: ' % (name, len(d)) + ', '.join('%s %d' % (v, len(c.get(v, []))) for v in
               ('OK', 'CRASH', 'HANG', 'SILENT', 'DATALOSS', 'UNCLEAR')))
print('\n'.join(out))
with open(os.path.join(here, 'report.md')) as f:
    text = f.read()
mark = '<!-- tables -->'
text = text.split(mark)[0] + mark + '\n\n## Table: adv35\'s non-OK cases re-run\n\n' + \
    table(RERUN, os.path.join(here, '..', 'adv35', 'cases'), 'rerun') + \
    '\n\n## Table: new cases\n\n' + table(NEW, os.path.join(here, 'cases'), 'new') + '\n'
with open(os.path.join(here, 'report.md'), 'w') as f:
    f.write(text)

#!/usr/bin/python3
"""mkreport.py: the tables of report.md from verdicts.py, the cases' headers and out/<new|p2>/<id>.txt (adv38)"""
import os, re, sys
here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, here)
from verdicts import NEW, P2

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
            and l != 'FOAM exiting' and not l.startswith('[case exit') and not re.match(r'^(\[\d\] *)+$', l)]
    tail = [l for l in lines if l.startswith('[case exit')]
    s = ' / '.join(keep[:n])
    if len(s) > width:
        s = s[:width] + ' ...'
    s += ' ' + (tail[-1] if tail else '')
    return s.replace('|', '\\|')

def where(k):
    """(case script, output) of a key: xNN (adv38) or adv36:vNN, adv37:wNN (earlier passes' reproducers, rerun.sh)"""
    if ':' in k:
        pas, v = k.split(':')
        return os.path.join(here, '..', pas, 'cases', v + '.sh'), pas + '_' + v + '.txt'
    return os.path.join(here, 'cases', k + '.sh'), k + '.txt'

def table(d, outDir):
    rows = ['| id | class | input | observed (first lines, [case exit, time]) | verdict |', '|---|---|---|---|---|']
    for k in sorted(d, key=lambda k: (':' in k, k)):
        cls, v, why = d[k]
        script, out = where(k)
        inp = header(script).replace('|', '\\|')
        obs = observed(os.path.join(here, 'out', outDir, out))
        verdict = '**%s**: %s' % (v, why.replace('|', '\\|'))
        rows.append('| %s | %s | %s | %s | %s |' % (k, cls, inp, obs, verdict))
    return '\n'.join(rows)

def counts(d):
    c = {}
    for k, (cls, v, why) in d.items():
        c.setdefault(v, []).append(k)
    return c

for name, d in (('phase 1 (new)', NEW), ('phase 2', P2)):
    c = counts(d)
    print('%s: %d cases: ' % (name, len(d)) + ', '.join('%s %d' % (v, len(c.get(v, []))) for v in
          ('OK', 'CRASH', 'HANG', 'SILENT', 'DATALOSS', 'UNCLEAR')))
with open(os.path.join(here, 'report.md')) as f:
    text = f.read()
mark = '<!-- tables -->'
text = text.split(mark)[0] + mark + '\n\n## Table: phase 1, new cases (main 6fd9435)\n\n' + table(NEW, 'new')
if P2:
    text += '\n\n## Table: phase 2, re-runs after the merge\n\n' + table(P2, 'p2')
with open(os.path.join(here, 'report.md'), 'w') as f:
    f.write(text + '\n')

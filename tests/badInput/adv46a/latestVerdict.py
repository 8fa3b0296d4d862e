#!/usr/bin/python3
"""latestVerdict.py [PASS ID]...: for each case (default: queueN.txt), the verdict of the LATEST report that has a table
row for it (adv45, adv44, adv43, adv42 (its phase-C table first), adv41, adv40, ...): the row's last cell's first word (OK, CRASH, HANG,
SILENT, DATALOSS, UNCLEAR; "(low)" kept; its last such row in that report), with the report's name; a case judged only in a pass's verdict-count summary
(adv35) or in phase-A "all OK" statements gets 'OK (no row)'."""
import re, os, sys
bi = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
W = ('CRASH', 'HANG', 'SILENT', 'DATALOSS', 'UNCLEAR', 'OK')
def rows(P):
    out = []
    for l in open('%s/%s/report.md' % (bi, P)):
        if l.startswith('|'):
            c = [x.strip() for x in l.strip().strip('|').split('|')]
            out.append(c)
    return out
order = ['adv45', 'adv44', 'adv43', 'adv42', 'adv41', 'adv40', 'adv39', 'adv38', 'adv37', 'adv36', 'adv35']
R = {P: rows(P) for P in order}
def verdict(p, i):
    for P in order:
        for c in reversed(R[P]):
            first = c[0].replace('*', '')
            cur, hit = P, False
            for tok in re.findall(r'adv3[5-9]|adv4[0-5]|\b[a-z]\d{2,3}\b', first):
                if tok.startswith('adv'): cur = tok
                elif cur == p and tok == i: hit = True
            if not hit: continue
            for cell in reversed(c[1:]):
                w = cell.replace('*', '').strip()
                if w.split(' ')[0].strip('(),;') in W:
                    return '%s [%s]' % (w[:40], P)
    return 'OK (no row)'
args = sys.argv[1:]
cases = [tuple(args[k:k + 2]) for k in range(0, len(args), 2)] if args else [tuple(l.split()) for l in open(os.path.join(bi, 'adv46a', 'queueN.txt'))]
for p, i in cases: print(p, i, '|', verdict(p, i))

#!/usr/bin/env python3
"""Instruction-level self cost (Ir) of the functions of a callgrind output
made with --dump-instr=yes, beside their disassembly (issue 18 item 5d,
branch perf45: where the instructions of a kernel go when the build has no
line information).

    instructionProfile.py CGOUT PATTERN [--calls N] [--min IR] [--all]

CGOUT    a callgrind.out file of valgrind --tool=callgrind --dump-instr=yes
PATTERN  a regular expression on the (demangled) function names; every
         function that matches is listed, largest self cost first
--calls  divide the counts by N (e.g. the passes or stages profiled)
--min    list only instructions with at least this self Ir (after --calls)
--all    list every instruction of the function, also those never run

Per function: its self Ir, then for each instruction its address, the
self Ir and the instruction (objdump -d --no-show-raw-insn of the object,
demangled), and a summary by kind (loads and stores through memory
operands, SSE arithmetic, moves between registers, integer and branch).
The addresses of a shared object are its file's addresses (as objdump's).
"""
import argparse
import re
import subprocess
import sys
from collections import defaultdict


def parse(path):
    """{(object, function): {address: self Ir}}"""
    names = {'ob': {}, 'fn': {}, 'fl': {}}
    cost = defaultdict(lambda: defaultdict(int))
    ob = fn = None
    last = [0, 0]           # the last position (instr, line)
    skip_next = False       # the cost line after calls= is inclusive
    num = re.compile(r'^[0-9+\-*]')

    def name(kind, text):
        m = re.match(r'\((\d+)\)\s*(.*)$', text)
        if not m:
            return text
        if m.group(2):
            names[kind][m.group(1)] = m.group(2)
        return names[kind].get(m.group(1), text)

    def pos(tok, i):
        if tok == '*':
            return last[i]
        if tok[0] in '+-':
            return last[i] + int(tok, 0)
        return int(tok, 0)

    for line in open(path, errors='replace'):
        line = line.rstrip('\n')
        if not line:
            continue
        if line.startswith('ob='):
            ob = name('ob', line[3:])
        elif line.startswith(('cob=', 'cfi=', 'cfl=')):
            key = {'cob': 'ob', 'cfi': 'fl', 'cfl': 'fl'}[line.split('=')[0]]
            name(key, line.split('=', 1)[1])
        elif line.startswith('cfn='):
            name('fn', line[4:])
        elif line.startswith('fn='):
            fn = name('fn', line[3:])
        elif line.startswith(('fl=', 'fi=', 'fe=')):
            name('fl', line[3:])
        elif line.startswith('calls='):
            skip_next = True
        elif num.match(line):
            toks = line.split()
            a = pos(toks[0], 0)
            ln = pos(toks[1], 1) if len(toks) > 2 else last[1]
            last[0], last[1] = a, ln
            if skip_next:
                skip_next = False
                continue
            ir = int(toks[-1]) if len(toks) >= 3 else 0
            cost[(ob, fn)][a] += ir
    return cost


def disassemble(obj, lo, hi):
    out = subprocess.run(
        ['objdump', '-d', '-C', '--no-show-raw-insn',
         '--start-address=%#x' % lo, '--stop-address=%#x' % hi, obj],
        capture_output=True, text=True).stdout
    ins = {}
    for l in out.splitlines():
        m = re.match(r'\s*([0-9a-f]+):\s*(.*)$', l)
        if m:
            ins[int(m.group(1), 16)] = m.group(2).strip()
    return ins


def kind(text):
    op = text.split()[0] if text else ''
    mem = '(' in text
    if op.startswith(('j', 'call', 'ret', 'cmp', 'test')) or op in ('jmp',):
        return 'branch/compare'
    if op.startswith(('mov', 'vmov')) and ('xmm' in text or 'ymm' in text):
        if mem:
            return 'SSE load/store'
        return 'SSE register move'
    if 'xmm' in text or op.startswith(('sqrt', 'div', 'mul', 'add', 'sub',
                                       'max', 'min', 'ucomi', 'comi',
                                       'and', 'xorp', 'unpck', 'shufp')):
        return 'SSE arithmetic' + (' (memory operand)' if mem else '')
    if op.startswith(('mov', 'lea', 'push', 'pop')):
        return 'integer load/store' if mem else 'integer move/lea'
    return 'integer other'


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('cgout')
    ap.add_argument('pattern')
    ap.add_argument('--calls', type=float, default=1.0)
    ap.add_argument('--min', type=float, default=0.0)
    ap.add_argument('--all', action='store_true')
    a = ap.parse_args()
    cost = parse(a.cgout)
    pat = re.compile(a.pattern)
    hits = [(sum(v.values()), k, v) for k, v in cost.items()
            if k[1] and pat.search(k[1])]
    if not hits:
        sys.exit('instructionProfile.py: no function matches ' + a.pattern)
    for total, (ob, fn), per in sorted(hits, reverse=True):
        print('== %s\n   [%s] self Ir %.4g' % (fn, ob, total/a.calls))
        lo, hi = min(per), max(per)
        ins = disassemble(ob, lo, hi + 16)
        kinds = defaultdict(float)
        for addr in sorted(set(ins) | set(per)):
            if addr > hi:
                break
            ir = per.get(addr, 0)/a.calls
            text = ins.get(addr, '?')
            kinds[kind(text)] += ir
            if (ir > 0 and ir >= a.min) or a.all:
                print('%10x %12.1f  %s' % (addr, ir, text))
        print('   by kind:')
        for k, v in sorted(kinds.items(), key=lambda x: -x[1]):
            print('   %-32s %12.1f  %5.1f %%' % (k, v, 100*v/(total/a.calls)))
        print()


if __name__ == '__main__':
    main()

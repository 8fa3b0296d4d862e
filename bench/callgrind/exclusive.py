#!/usr/bin/env python3
"""Exclusive instruction counts (Ir) per function of callgrind output files,
serial against the sum over the ranks of a parallel run (issue 18 item 5,
branch eff18e).

    exclusive.py SERIAL RANK0 [RANK1 ...] [--top N] [--min IR]

SERIAL, RANKi: callgrind.out files of the same case and steps (e.g.
bench/callgrind/loopProfile.sh's cg.serial, cg.rank0, cg.rank1), of one
build or of two (objects are compared by file name, not directory).
Each function's exclusive Ir (its own instructions, not its callees') is
summed over its object; functions of Open MPI's libraries and their
components (libmpi, libopen-pal, libopen-rte, mca_*, libucs/libucp,
libfabric, libhwloc, libevent) and of OpenFOAM's Pstream are counted as
"MPI" (the progress loop polls, and counts instructions, while a rank
waits), the rest as work. Prints the totals (serial, each rank, the sum of
the ranks, the ratio sum/serial with and without MPI), the largest
differences sum - serial per function (work only) and per object.
"""
import argparse
import re
import sys
from collections import defaultdict

MPI_OBJ = re.compile(r'(libmpi|libopen-pal|libopen-rte|^mca_|libucs|libucp|'
                     r'libuct|libfabric|libhwloc|libevent|libpmix|'
                     r'libPstream|openmpi)')


def parse(path):
    """{(object, function): exclusive Ir}, total Ir"""
    cost = defaultdict(int)
    names = {'ob': {}, 'fn': {}}
    ob = fn = None
    skip = False
    events = None
    with open(path, errors='replace') as f:
        for line in f:
            if not line or line[0] == '\n':
                continue
            c = line[0]
            if c.isdigit() or c in '+-*':
                if skip:
                    skip = False
                    continue
                parts = line.split()
                if len(parts) >= 2:
                    cost[(ob, fn)] += int(parts[1])
                continue
            key, _, val = line.rstrip('\n').partition('=')
            if key in ('ob', 'fn', 'cob', 'cfn'):
                kind = key[-2:]
                m = re.match(r'\((\d+)\)(?: (.*))?$', val)
                if m:
                    if m.group(2) is not None:
                        names[kind][m.group(1)] = m.group(2)
                    name = names[kind].get(m.group(1), val)
                else:
                    name = val
                if key == 'ob':
                    # the file name only: two builds' copies of a library
                    # compare as one
                    ob = name.rsplit('/', 1)[-1]
                elif key == 'fn':
                    fn = name
            elif key == 'calls':
                skip = True
            elif key == 'events':
                events = val.split()
    if events and events[0] != 'Ir':
        sys.exit(f'{path}: first event {events[0]}, not Ir')
    return cost


def isMpi(ob, fn):
    return bool(MPI_OBJ.search(ob or '')) or fn.startswith(('MPI_', 'PMPI_',
                                                            'ompi_', 'opal_'))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('serial')
    ap.add_argument('ranks', nargs='+')
    ap.add_argument('--top', type=int, default=30)
    args = ap.parse_args()
    s = parse(args.serial)
    rs = [parse(r) for r in args.ranks]
    keys = set(s)
    for r in rs:
        keys |= set(r)

    def split(c):
        mpi = sum(v for (o, f), v in c.items() if isMpi(o, f or ''))
        return sum(c.values()) - mpi, mpi

    sw, sm = split(s)
    print(f'serial: {sw:.4e} Ir work, {sm:.4e} Ir MPI')
    tw = tm = 0
    for i, r in enumerate(rs):
        w, m = split(r)
        tw += w
        tm += m
        print(f'rank {i}: {w:.4e} Ir work, {m:.4e} Ir MPI')
    print(f'sum over the ranks: {tw:.4e} Ir work, {tm:.4e} Ir MPI')
    print(f'ratio sum/serial: work {tw/sw:.4f}, with MPI '
          f'{(tw + tm)/(sw + sm):.4f}; extra work {tw - sw:.4e} Ir')
    rows = []
    for k in keys:
        if isMpi(k[0], k[1] or ''):
            continue
        a = s.get(k, 0)
        b = sum(r.get(k, 0) for r in rs)
        rows.append((b - a, a, [r.get(k, 0) for r in rs], k))
    rows.sort(key=lambda x: -abs(x[0]))
    print(f'\nlargest differences, sum over the ranks - serial (work, '
          f'% of the serial work {sw:.4e} Ir):')
    print('| function | object | serial [Ir] | ' +
          ' | '.join(f'rank {i} [Ir]' for i in range(len(rs))) +
          ' | sum - serial [Ir] | % of serial work |')
    print('|---|---|---|' + '---|'*len(rs) + '---|---|')
    for d, a, b, (o, f) in rows[:args.top]:
        print(f'| `{f[:110]}` | {o.rsplit("/", 1)[-1] if o else "?"} | '
              f'{a:.4g} | ' + ' | '.join(f'{x:.4g}' for x in b) +
              f' | {d:+.4g} | {100*d/sw:+.2f} |')
    byObj = defaultdict(lambda: [0, 0])
    for (o, f), v in s.items():
        byObj[o][0] += v
    for r in rs:
        for (o, f), v in r.items():
            byObj[o][1] += v
    print('\nby object (all functions): | object | serial | sum | diff |')
    for o, (a, b) in sorted(byObj.items(), key=lambda x: -abs(x[1][1]
                                                               - x[1][0])):
        if abs(b - a) > 1e-4*sw:
            print(f'| {o} | {a:.4g} | {b:.4g} | {b - a:+.4g} |')


if __name__ == '__main__':
    main()

#!/usr/bin/python3
"""Summary of bench/mpiWait's records of one run (every rank's
PREFIX.rank<r> and PREFIX.rank<r>.trace).

    bench/mpiWait/summary.py PREFIX [--steps N] [--top K]

Per exchange site (the call stack up to the project's function that made
it, OpenFOAM's Pstream layer left out): MPI calls per time step, wall
seconds inside them per rank (on a loaded machine mostly a partner that
was descheduled), and the load-independent estimate of a quiet machine:
the ranks' synchronising calls paired in order (each rank's sequence of
collectives, waits and probes; aligned where a rank made extra ones), the
work before each one (the rank's thread CPU time outside MPI since its
previous synchronising call), and the wait it implies, the largest work
of the ranks minus the rank's own, summed per site. The sum of the
largest works is the critical path of the ranks' work, i.e. the time
loop of a quiet machine without the exchanges' own cost.
"""
import argparse
import difflib
import glob
import re
import struct
import sys

SKIP = re.compile(r'(UPstream|UIPstream|UOPstream|Pstream::|libmpi|'
                  r'libmpiWait|^\?$|libc\.so)')
STOP = re.compile(r'(fluidSolidInteraction::(step|setDeltaT|write|report)'
                  r'|Time::run|^main$)')


def readSites(path):
    sites = {}
    header = None
    cur = None
    with open(path) as f:
        for line in f:
            if line.startswith('#'):
                header = line.strip()
            elif line.startswith('site '):
                w = line.split()
                cur = {'id': int(w[1]), 'fn': w[2], 'calls': int(w[4]),
                       'seconds': float(w[6]), 'frames': []}
                sites[cur['id']] = cur
            else:
                cur['frames'].append(line.strip())
    for s in sites.values():
        names = []
        for fr in s['frames']:
            lib, _, fn = fr.partition('!')
            if SKIP.search(fr) or fn == '?':
                continue
            names.append(fn)
            if STOP.search(fn):
                break
        # the site: the project's call, whichever MPI function made it
        # (a gather waits in MPI_Waitall on the master, in MPI_Recv on
        # the others)
        s['label'] = ' < '.join(names)
    return header, sites


def readTrace(path):
    data = open(path, 'rb').read()
    return [struct.unpack_from('<iff', data, 12*i)
            for i in range(len(data)//12)]


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    ap.add_argument('prefix')
    ap.add_argument('--steps', type=float, default=1,
                    help='time steps of the run (per-step counts)')
    ap.add_argument('--top', type=int, default=40)
    a = ap.parse_args()
    files = sorted(glob.glob(a.prefix + '.rank[0-9]*'))
    files = [f for f in files if not f.endswith('.trace')]
    if len(files) != 2:
        sys.exit('summary.py: the pairing is written for 2 ranks, found '
                 + str(len(files)))
    ranks = [readSites(f) for f in files]
    traces = [readTrace(f + '.trace') for f in files]
    for h, _ in ranks:
        print(h)

    # per label: calls and wall seconds per rank (all MPI calls)
    labels = {}
    for r, (_, sites) in enumerate(ranks):
        for s in sites.values():
            e = labels.setdefault(s['label'], [[0, 0.0], [0, 0.0]])
            e[r][0] += s['calls']
            e[r][1] += s['seconds']

    # pairing of the synchronising calls by their labels
    seqs = [[ranks[r][1][ev[0]]['label'] for ev in traces[r]]
            for r in range(2)]
    sm = difflib.SequenceMatcher(None, seqs[0], seqs[1], autojunk=False)
    paired = {}
    pathSum = 0.0
    workSum = [0.0, 0.0]
    nPaired = 0
    for blk in sm.get_matching_blocks():
        for k in range(blk.size):
            e0 = traces[0][blk.a + k]
            e1 = traces[1][blk.b + k]
            lab = seqs[0][blk.a + k]
            w0, w1 = e0[1], e1[1]
            m = max(w0, w1)
            p = paired.setdefault(lab, [0, 0.0, 0.0, 0.0, 0.0])
            p[0] += 1
            p[1] += m - w0
            p[2] += m - w1
            p[3] += w0
            p[4] += w1
            pathSum += m
            workSum[0] += w0
            workSum[1] += w1
            nPaired += 1
    print('synchronising calls: rank 0 %d, rank 1 %d, paired %d'
          % (len(seqs[0]), len(seqs[1]), nPaired))
    print('paired work [s]: rank 0 %.3f, rank 1 %.3f; critical path (sum of'
          ' the larger) %.3f; implied waiting: rank 0 %.3f, rank 1 %.3f'
          % (workSum[0], workSum[1], pathSum, pathSum - workSum[0],
             pathSum - workSum[1]))
    print()
    print('%9s %9s %8s %8s %8s %8s %8s %8s  %s' %
          ('calls/st', 'syncs', 'wall0', 'wall1', 'work0', 'work1',
           'iwait0', 'iwait1', 'site'))
    rows = []
    for lab, e in labels.items():
        p = paired.get(lab, [0, 0.0, 0.0, 0.0, 0.0])
        rows.append((max(p[1], p[2]) + 1e-6*(e[0][0] + e[1][0]), lab, e, p))
    rows.sort(reverse=True)
    for _, lab, e, p in rows[:a.top]:
        print('%9.2f %9d %8.3f %8.3f %8.3f %8.3f %8.3f %8.3f  %s' %
              (max(e[0][0], e[1][0])/a.steps, p[0], e[0][1], e[1][1],
               p[3], p[4], p[1], p[2], lab[:260]))
    tot = [sum(e[r][0] for e in labels.values()) for r in range(2)]
    print('all MPI calls per step: rank 0 %.1f, rank 1 %.1f'
          % (tot[0]/a.steps, tot[1]/a.steps))


if __name__ == '__main__':
    main()

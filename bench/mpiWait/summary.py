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
import glob
import re
import struct
import sys

SKIP = re.compile(r'(UPstream|UIPstream|UOPstream|Pstream::|libmpi|'
                  r'libmpiWait|^\?$|libc\.so)')
STOP = re.compile(r'(fluidSolidInteraction::(step|setDeltaT|write|report)'
                  r'|Time::run|^main$)')


# cellBlastFoam's exchange sites by part (the first pattern that matches)
GROUPS = (
    ('fluid stage: processor patches', r'conservativeFluid::(aleStep|fluxes)'
     r'|MUSCLReconstruction|rhoEThermo::correct'),
    ('interface faces (gathers)', r'globalInterfacePatch::(faceValues|'
     r'packedFaceValues)|wallFaceValues'),
    ('solid step (all-gather)', r'combineParts'),
    ('mesh motion', r'bandMeshMotion::notify|fluidSolidInteraction::moveWall'),
    ('Courant number', r'courantNumber|setDeltaT'),
    ('step totals, solid output', r'^Foam::fluidSolidInteraction::step$'
     r'|^solid::Partition::combine < Foam::fluidSolidInteraction::step$'),
    ('solid output', r'solidDomain::write'),
    ('water probes', r'movingMeshProbes::write'),
    ('start-up and end', r''),
)


def group(label):
    for name, pattern in GROUPS:
        if re.search(pattern, label):
            return name
    return GROUPS[-1][0]


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


def align(a, b, look=200):
    """Pairs (i, j) of equal labels of two nearly equal sequences, in
    order: where they differ, the nearest resynchronisation within look
    calls of either"""
    i = j = 0
    out = []
    while i < len(a) and j < len(b):
        if a[i] == b[j]:
            out.append((i, j))
            i += 1
            j += 1
            continue
        best = None
        for d in range(1, look):
            for di, dj in ((d, 0), (0, d)) + tuple((k, d - k) for k in range(1, d)):
                if i + di < len(a) and j + dj < len(b) and a[i + di] == b[j + dj]:
                    best = (di, dj)
                    break
            if best:
                break
        if not best:
            i += 1
            j += 1
            continue
        i += best[0]
        j += best[1]
    return out


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
    # consecutive calls of one site are one synchronisation (a gather and
    # a scatter: one call on the master, two on the others): merged, their
    # works added
    seqs = [[], []]
    merged = [[], []]
    for r in range(2):
        for ev in traces[r]:
            lab = ranks[r][1][ev[0]]['label']
            if seqs[r] and seqs[r][-1] == lab:
                w = merged[r][-1]
                merged[r][-1] = (w[0], w[1] + ev[1], w[2] + ev[2])
            else:
                seqs[r].append(lab)
                merged[r].append(ev)
    traces = merged
    pairs = align(seqs[0], seqs[1])
    paired = {}
    pathSum = 0.0
    workSum = [0.0, 0.0]
    nPaired = 0
    for i, j in pairs:
        e0 = traces[0][i]
        e1 = traces[1][j]
        lab = seqs[0][i]
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
    print()
    print('by part: synchronisations per step (consecutive calls of a site'
          ' as one), implied waiting per rank [s]')
    byGroup = {}
    for lab, p in paired.items():
        g = byGroup.setdefault(group(lab), [0, 0.0, 0.0])
        g[0] += p[0]
        g[1] += p[1]
        g[2] += p[2]
    for name, _ in GROUPS:
        if name in byGroup:
            g = byGroup[name]
            print('  %-32s %7.2f %8.3f %8.3f' % (name, g[0]/a.steps, g[1], g[2]))
    print('  %-32s %7.2f %8.3f %8.3f' % ('all', nPaired/a.steps,
          pathSum - workSum[0], pathSum - workSum[1]))
    tot = [sum(e[r][0] for e in labels.values()) for r in range(2)]
    print('all MPI calls per step: rank 0 %.1f, rank 1 %.1f'
          % (tot[0]/a.steps, tot[1]/a.steps))


if __name__ == '__main__':
    main()

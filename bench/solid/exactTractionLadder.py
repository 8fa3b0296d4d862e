#!/usr/bin/python3
"""The lateral strain of bench/solid/exactTraction runs along a ladder of
solid meshes (issue 17 item 4; docs/results/blastPlaneWave.md, "The solid
alone under the exact traction"; not a test).

Usage: exactTractionLadder.py [-depth D] [-nucleus AN,CN,E[,E1]]
                              [-exclude R,Z,E] [-where] H=DIR [H=DIR ...]

Each DIR a run of build/bin/exactTraction with -fields (and its probes,
after bench/solid/exactTraction.py); H its solid element size [m]. The
exact answer is uniaxial strain: the lateral strain ln J - ln|F e_z| is 0
everywhere. Per run and field time: the rms and the largest |lateral
strain| over the elements whose centroid lies deeper than D (default
1e-6 m) below the loaded surface (the fields' depth column), and the
observed order of the rms between successive runs; with -nucleus also
leaving out the elements whose centroid lies within E [m] of the
nucleus surface (r/AN)^2 + (z/CN)^2 = 1 (the scaled cell's: AN 5.82405e-6,
CN 5.47737e-6; the distance |f|/|grad f| of that level function); with
-nucleus AN,CN,E,E1 only the elements whose centroid lies between E and
E1 [m] from it (a band: E 0 includes the surface's own elements); with
-exclude R,Z,E also leaving out the elements whose centroid lies within
E [m] of the point (R, Z) [m] (e.g. the nucleus O-grid's node of 3
elements); with -where each largest |lateral strain| with its element's
centroid (r, z) [um]. Then,
per probe of
bench/blast/ballLadder.py (the same measures as for a coupled run): the
von Mises 1-ns peak's error against the exact answer and its non-uniaxial
part (b) per run, and the largest |error| and |(b)| over the point probes
(the band* probes left out, as ballLadder.py does).
"""
import glob
import math
import os
import sys

import numpy as np

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, "..", "blast"))
import ballLadder   # noqa: E402


def fields(d, depth, nucleus=None, exclude=None, where=False):
    """{time [s]: (rms, largest |lateral|, elements)} over depth > D (and
    farther than E from the nucleus surface, nucleus = (AN, CN, E))"""
    out = {}
    for f in glob.glob(os.path.join(d, "fields", "*.dat")):
        with open(f) as fh:
            t = float(fh.readline().split()[3])
        a = np.genfromtxt(f, comments="#", usecols=(2, 3, 6, 11))
        r, z, lat, dep = a[:, 0], a[:, 1], a[:, 2], a[:, 3]
        m = dep > depth
        if nucleus:
            an, cn, e = nucleus[:3]
            level = (r/an)**2 + (z/cn)**2 - 1
            dist = abs(level)/(2*np.hypot(r/an**2, z/cn**2))
            m &= dist >= e if len(nucleus) == 4 else dist > e
            if len(nucleus) == 4:
                m &= dist < nucleus[3]
        if exclude:
            m &= np.hypot(r - exclude[0], z - exclude[1]) > exclude[2]
        if not m.any():
            sys.exit("exactTractionLadder.py: %s: no element deeper than %g"
                     " m" % (f, depth))
        out[t] = (math.sqrt((lat[m]**2).mean()), abs(lat[m]).max(),
                  int(m.sum()))
        if where:
            # and the largest's element centroid
            k = np.argmax(np.where(m, abs(lat), -1))
            out[t] += ((r[k], z[k]),)
    if not out:
        sys.exit("exactTractionLadder.py: %s: no fields/*.dat (run "
                 "exactTraction with -fields)" % d)
    return out


def main():
    args = sys.argv[1:]
    depth = 1e-6
    nucleus = None
    exclude = None
    where = "-where" in args
    args = [a for a in args if a != "-where"]
    while args[:1] in (["-depth"], ["-nucleus"], ["-exclude"]) \
            and len(args) > 1:
        if args[0] == "-depth":
            depth = float(args[1])
        elif args[0] == "-exclude":
            exclude = tuple(float(x) for x in args[1].split(","))
            if len(exclude) != 3 or exclude[2] <= 0:
                sys.exit("exactTractionLadder.py: -exclude R,Z,E: a point "
                         "[m] and a positive distance E [m]")
        else:
            nucleus = tuple(float(x) for x in args[1].split(","))
            if not (len(nucleus) in (3, 4) and all(x > 0 for x in
                                                   nucleus[:2])
                    and all(x >= 0 for x in nucleus[2:])
                    and (len(nucleus) == 3 or nucleus[3] > nucleus[2])):
                sys.exit("exactTractionLadder.py: -nucleus AN,CN,E[,E1]: "
                         "positive lengths AN, CN [m], E >= 0 m, E1 > E")
        args = args[2:]
    if not args:
        sys.exit(__doc__)
    runs = []
    for a in args:
        h, d = a.split("=", 1)
        runs.append((float(h), d, fields(d, depth, nucleus, exclude,
                                         where)))
    runs.sort(key=lambda r: -r[0])
    times = sorted(runs[0][2])
    print("| field time [ns] | " + " | ".join(
        "H %g um: rms / largest |lateral strain| (elements)" % (h*1e6)
        for h, _, _ in runs) + " | observed order of the rms |")
    print("|---:|" + "---:|"*len(runs) + "---|")
    for t in times:
        cells, rms = [], []
        for h, _, f in runs:
            k = min(f, key=lambda x: abs(x - t))
            r, m, n = f[k][:3]
            cells.append("%.2e / %.2e (%d)" % (r, m, n) if not where else
                         "%.2e / %.2e (%d; at %.2f, %.2f)"
                         % (r, m, n, f[k][3][0]*1e6, f[k][3][1]*1e6))
            rms.append(r)
        orders = ["%.2f" % (math.log(rms[i]/rms[i + 1])
                            / math.log(runs[i][0]/runs[i + 1][0]))
                  for i in range(len(rms) - 1)]
        print("| %.1f | %s | %s |" % (t*1e9, " | ".join(cells),
                                      ", ".join(orders)))
    print()
    res = [(h, ballLadder.run("%g=%s" % (h, d), verify=False)[1]) for h, d, _ in runs]
    names = [k for k in res[0][1] if not k.startswith("band")]
    print("| probe | " + " | ".join("H %g um: error; (b)" % (h*1e6)
                                    for h, _ in res) + " |")
    print("|---|" + "---:|"*len(res))
    for k in names:
        print("| %s | %s |" % (k, " | ".join(
            "%+.2f %%; %+.2f %%" % (100*(o[k]["vm"]/o[k]["ref"] - 1),
                                    100*(o[k]["vm"]/o[k]["vmJ"] - 1))
            for _, o in res)))
    points = [k for k in names if not k.startswith("ball")]
    print("| largest over the point probes | %s |" % " | ".join(
        "%.2f %%; %.2f %%" % (
            max(abs(100*(o[k]["vm"]/o[k]["ref"] - 1)) for k in points),
            max(abs(100*(o[k]["vm"]/o[k]["vmJ"] - 1)) for k in points))
        for _, o in res))


if __name__ == "__main__":
    main()

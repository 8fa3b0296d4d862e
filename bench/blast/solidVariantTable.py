#!/usr/bin/python3
"""Markdown table of solidVariant.sh runs against the exact plane wave.

    bench/blast/solidVariantTable.py LABEL=DIR [LABEL=DIR ...]

DIR: a folder of bench/blast/solidVariant.sh (its axisymmetricPreview with
planeWave -check run). Per run: the errors of the 1-ns peaks of von Mises
and strain at the Fig. 10 point (cytoplasm / nucleus side) and at the bulk
probes (nucleusBulk / cytoplasmBulk, when present), the solid pressure's
1-ns peak at the Fig. 10 point, the largest rest strain after 140 ns over
the solid probes, the largest von Mises along the membrane-cytoplasm and
cytoplasm-nucleus interfaces up to 90 ns (postProcessing/solidInterfaces,
the first passage), and cellBlastFoam's CPU time (time.log). Not a test
(docs/results/blastPlaneWave.md).
"""
import os
import re
import sys

from neuronFsi import script  # noqa: E402
script.guard()  # an input's error: one line, exit 1 (adv53 u12)
from neuronFsi import planeWave


def rows(path):
    """{probe: its row's values in column order} (the first row of each
    probe) of a planeWave measures file"""
    out = {}
    for r in planeWave.readMeasures(path):
        out.setdefault(r["probe"], list(r.values()))
    return out


def interfaceMaxima(case, tEnd=90e-9):
    """'m-c / c-n' von Mises maxima [Pa] up to tEnd, or '-'"""
    path = os.path.join(case, "postProcessing", "solidInterfaces", "0",
                        "interfaceMaxima.dat")
    if not os.path.exists(path):
        return "-"
    mc = cn = 0.0
    with open(path) as f:
        for line in f:
            if line.startswith("#") or not line.strip():
                continue
            w = [float(x) for x in line.split()]
            if w[0] <= tEnd:
                mc, cn = max(mc, w[2]), max(cn, w[4])
    return "%.2f / %.2f" % (mc, cn)


def main(args):
    if not args:
        sys.exit(__doc__)
    print("| run | von Mises at the Fig. 10 point, cytoplasm / nucleus [%] "
          "| strain there [%] | von Mises in the bulk, nucleus / cytoplasm "
          "[%] | solid pressure 1-ns peak at the Fig. 10 point [%] "
          "| largest rest strain [-] | interface von Mises maxima to "
          "90 ns, m-c / c-n [Pa] | CPU [s] |")
    print("|---|---|---|---|---|---|---|---:|")
    for arg in args:
        label, _, d = arg.partition("=")
        case = os.path.join(d, "axisymmetricPreview")
        pw = os.path.join(case, "postProcessing", "planeWave", "0")
        s = rows(os.path.join(pw, "solidMeasures.dat"))
        m = rows(os.path.join(pw, "measures.dat"))
        # solidMeasures: probe region z vM vMref errVM strain ref errStrain
        # rest restVM; the Fig. 10 point's two sides are the last two
        # probes, the bulk probes (if any) the first two
        side = [w for w in s.values() if float(w[2]) > 4e-6]
        bulk = [w for w in s.values() if float(w[2]) <= 4e-6]
        cyto = next(w for w in side if w[1] == "cytoplasm")
        nuc = next(w for w in side if w[1] == "nucleus")
        vb = " / ".join("%+.1f" % float(w[5]) for w in bulk) or "-"
        p = next(w for k, w in m.items() if k.startswith("solid_p")
                 and float(w[1]) > 4e-6)
        rest = max(float(w[9]) for w in s.values())
        cpu = "-"
        tl = os.path.join(case, "time.log")
        if os.path.exists(tl):
            g = re.search(r"([0-9.]+) s CPU", open(tl).read())
            cpu = g.group(1) if g else "-"
        print("| %s | %+.1f / %+.1f | %+.1f / %+.1f | %s | %+.1f | %.2g | %s "
              "| %s |" % (label, float(cyto[5]), float(nuc[5]),
                          float(cyto[8]), float(nuc[8]), vb, float(p[13]),
                          rest, interfaceMaxima(case), cpu))


if __name__ == "__main__":
    main(sys.argv[1:])

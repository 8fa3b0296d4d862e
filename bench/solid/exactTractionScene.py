#!/usr/bin/python3
"""The solid alone under the exact traction against the coupled scene, at
the same probes (issue 17 item 4; docs/results/blastPlaneWave.md, "The
solid alone under the exact traction"; not a test).

Usage: exactTractionScene.py [-reference FILE] H=ALONE:SCENE [...]

ALONE a run of build/bin/exactTraction (after bench/solid/
exactTraction.py, on SCENE's cell.msh and probes), SCENE the coupled run
of bench/blast/transparentCell.sh with bench/blast/ballProbes.override
(FILE: the reference.dat for a SCENE without its own, as for
bench/blast/ballLadder.py). Per probe (the band* probes left out) and H:
bench/blast/ballLadder.py's von Mises error against the exact answer,
its non-uniaxial part (b) = von Mises / uniaxial(J) and the lateral
strain ln J - ln F_zz at the peak, alone and coupled; then over all rows
the correlation of the two runs' lateral strains and of their (b), the
mean and rms of scene - alone, and the rms of each. The errors are each
against its own exact answer (the scene's: planeWave's reference.dat, the
alone's: exactTraction.py's column); (b) and the lateral strain need
none.
"""
import os
import sys

import numpy as np

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, "..", "blast"))
import ballLadder   # noqa: E402


def main():
    args = sys.argv[1:]
    reference = None
    if args[:1] == ["-reference"] and len(args) > 1:
        reference, args = args[1], args[2:]
    if not args:
        sys.exit(__doc__)
    rows = []
    for a in args:
        h, dirs = a.split("=", 1)
        alone, scene = dirs.split(":", 1)
        _, oa = ballLadder.run("%s=%s" % (h, alone))
        _, os_ = ballLadder.run("%s=%s" % (h, scene), reference)
        for k in oa:
            if k.startswith("band") or k == "interfaceProbe.cytoplasm":
                continue
            if k not in os_:
                sys.exit("exactTractionScene.py: probe %s of %s not in %s"
                         % (k, alone, scene))
            rows.append((k, float(h), oa[k], os_[k]))
    rows.sort(key=lambda r: (r[0], -r[1]))

    def err(r):
        return 100*(r["vm"]/r["ref"] - 1)

    def b(r):
        return 100*(r["vm"]/r["vmJ"] - 1)

    print("| probe | -cell [um] | von Mises error: alone / scene | (b) "
          "vM / uniaxial(J): alone / scene | lateral strain at the peak: "
          "alone / scene |")
    print("|---|---:|---:|---:|---:|")
    for k, h, a, s in rows:
        print("| %s | %g | %+.2f %% / %+.2f %% | %+.2f %% / %+.2f %% | "
              "%+.2e / %+.2e |" % (k, h*1e6, err(a), err(s), b(a), b(s),
                                   a["lateral"], s["lateral"]))
    la = np.array([a["lateral"] for _, _, a, _ in rows])
    ls = np.array([s["lateral"] for _, _, _, s in rows])
    ba = np.array([b(a) for _, _, a, _ in rows])
    bs = np.array([b(s) for _, _, _, s in rows])
    print()
    for name, x, y, unit in (("lateral strain", la, ls, ""),
                             ("(b)", ba, bs, " %")):
        print("%s over %d rows: correlation %.3f; scene - alone mean "
              "%+.3g%s, rms %.3g%s; rms alone %.3g%s, scene %.3g%s"
              % (name, len(x), np.corrcoef(x, y)[0, 1], (y - x).mean(),
                 unit, np.sqrt(((y - x)**2).mean()), unit,
                 np.sqrt((x**2).mean()), unit, np.sqrt((y**2).mean()),
                 unit))


if __name__ == "__main__":
    main()

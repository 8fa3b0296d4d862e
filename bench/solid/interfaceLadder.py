#!/usr/bin/python3
"""The Fig. 10 point's ladder and its neighbourhood on the nucleus surface
(issue 17 item 4; docs/results/blastPlaneWave.md, "A map smooth across the
nucleus surface"; not a test).

Usage: interfaceLadder.py H=DIR [H=DIR ...]

Each DIR a run of bench/solid/structuredLadderRuns.sh (or any run that
bench/blast/ballLadder.py reads) whose probes were placed with
bench/solid/cellProbes.py -along DZ,K -normal D1,...; H its element size
[m]. Per run, against the exact answer (ballLadder.run): the 1-ns peaks
of von Mises and of the longitudinal strain ln|F e_z| (the most negative
1-ns mean) at

  fig10        the Fig. 10 point (interfaceProbe, cytoplasm side);
  along        the interface points interfaceProbe.zk (k = -K..K, the
               Fig. 10 point at k = 0; each on the discrete interface at
               the height z0 + k DZ, cytoplasm side): their mean, and the
               range min..max, i.e. how much the point's error moves with
               its place along the polygon at one level;
  nD           the points at the normal distance D [nm] from the exact
               nucleus surface into the cytoplasm (the same material point
               on every mesh).

Then for each of these the observed order p and the Richardson value from
the three finest runs (neuronFsi.convergence.threeLevel, Celik et al. 2008:
none if the changes alternate); if the changes alternate, the
oscillatory-convergence error bar of Celik et al. 2008 (J. Fluids Eng.
130:078001) / Roache: half the range of the three finest runs, as a
percentage of the exact value.
"""
import os
import sys

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, "..", "blast"))
import ballLadder   # noqa: E402
from neuronFsi import script  # noqa: E402
script.guard()  # an input's error: one line, exit 1 (fix19k: every script)
from neuronFsi import convergence   # noqa: E402


def measures(out):
    """{name: (vm, vmRef, strain, strainRef)} of the interface probes"""
    m = {}
    along = [k for k in out if k.startswith("interfaceProbe.z")]
    if "interfaceProbe" not in out:
        sys.exit("interfaceLadder.py: no interfaceProbe in the run")
    m["fig10"] = out["interfaceProbe"]
    offs = [k for k in out if k.startswith("interfaceProbe.n")
            and k[len("interfaceProbe.n"):].isdigit()]
    for k in sorted(offs, key=lambda k: int(k[len("interfaceProbe.n"):])):
        m[k[len("interfaceProbe."):]] = out[k]
    return m, [out["interfaceProbe"]] + [out[k] for k in along]


def err(v, ref):
    return 100*(v/ref - 1)


def main():
    args = sys.argv[1:]
    if not args:
        sys.exit(__doc__)
    runs = sorted((ballLadder.run(a) for a in args), key=lambda x: -x[0])
    print("| H [um] | Fig. 10 point: von Mises error; strain error | along "
          "the interface (%d points): von Mises error mean (min..max); "
          "strain error mean (min..max) | normal offsets: von Mises error; "
          "strain error |" % len(measures(runs[0][1])[1]))
    print("|---:|---:|---:|---|")
    series = {}
    for h, out in runs:
        m, al = measures(out)
        ev = [err(r["vm"], r["ref"]) for r in al]
        es = [err(r["strain"], r["strainRef"]) for r in al]
        f = m["fig10"]
        offs = [k for k in m if k != "fig10"]
        print("| %g | %+.2f %%; %+.2f %% | %+.2f %% (%+.2f..%+.2f); "
              "%+.2f %% (%+.2f..%+.2f) | %s |"
              % (h*1e6, err(f["vm"], f["ref"]),
                 err(f["strain"], f["strainRef"]),
                 sum(ev)/len(ev), min(ev), max(ev),
                 sum(es)/len(es), min(es), max(es),
                 "; ".join("%s %+.2f %%, %+.2f %%"
                           % (k, err(m[k]["vm"], m[k]["ref"]),
                              err(m[k]["strain"], m[k]["strainRef"]))
                           for k in offs)))
        # values (not errors) for Richardson; the exact values are the
        # same on every mesh for a fixed material point, and for the
        # along mean its points' exact values are too
        for k in ["fig10"] + offs:
            for q, qr in (("vm", "ref"), ("strain", "strainRef")):
                series.setdefault((k, q), []).append(
                    (h, m[k][q], m[k][qr]))
        for q, qr in (("vm", "ref"), ("strain", "strainRef")):
            series.setdefault(("along mean", q), []).append(
                (h, sum(r[q] for r in al)/len(al),
                 sum(r[qr] for r in al)/len(al)))
    if len(runs) < 3:
        return
    print()
    print("| measure | quantity | error against exact, H = %s um | "
          "observed order p | Richardson value's error against exact | "
          "finest's error against Richardson | oscillatory error bar "
          "(half the range of the 3 finest) |"
          % " / ".join("%g" % (h*1e6) for h, _ in runs))
    print("|---|---|---|---:|---:|---:|---:|")
    for (k, q), lv in series.items():
        l3 = lv[-3:]
        c = convergence.threeLevel([x[0] for x in l3], [x[1] for x in l3])
        v0, p = c.extrapolated, c.p
        ref = l3[-1][2]
        vals = [x[1] for x in l3]
        bar = 100*c.halfRange/abs(ref)
        print("| %s | %s | %s | %s | %s | %s | %.2f %% |"
              % (k, "von Mises" if q == "vm" else "strain",
                 " / ".join("%+.2f %%" % err(x[1], x[2]) for x in lv),
                 "-" if p is None else "%.2f" % p,
                 "-" if v0 is None else "%+.2f %%" % err(v0, ref),
                 "-" if v0 is None else "%+.2f %%" % err(vals[-1], v0),
                 bar))


if __name__ == "__main__":
    main()

#!/usr/bin/python3
"""checkExactTraction.py WORK: the bounds of tests/blast/exactTraction.sh
on its runs WORK/{aligned,random}-{0.35,0.25,0.175} (bench/solid/
exactTraction under the exact plane-wave traction; the exact answer is
uniaxial strain, lateral strain ln J - ln|F e_z| = 0). Exit 1 outside.

Aligned meshes (the structured grid):
  - the rms lateral strain over the elements deeper than 1 um at 66 and
    70 ns (the pulse in the block) below 3e-4 at 0.35 um and falling with
    each refinement at an observed order of at least 1 (measured with this
    test's 20 nm table: 9.6e-5 and 1.6e-4 at 0.35 um, orders 1.40, 1.61
    at 66 ns and 2.52, 1.31 at 70 ns; with the docs' 10 nm table 3.4e-4
    and 4.8e-4, orders 3.9, 2.0 and 3.2, 3.4: the sharper the table's
    front, the larger the mismatch with the solid's own front at the
    loaded side);
  - the von Mises 1-ns peak at r = 2 um, z = 4.108 um against the exact
    answer (ballLadder.py's measure) within 3 % at 0.175 um, its non-
    uniaxial part (b) within 0.3 % (measured -1.26 %, +0.09 %).
Random meshes (interior nodes moved by up to h/4): the same rms above 5
times the aligned mesh's at every size (measured 1.5e-3 against 4.5e-5
to 3.4e-4: the irregular quadrilaterals' lateral strain, which does not
fall with h; asserted so that the measure is seen to detect it).
"""
import os
import sys

root = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
sys.path.insert(0, os.path.join(root, "bench", "solid"))
import exactTractionLadder   # noqa: E402

SIZES = (0.35, 0.25, 0.175)


def main():
    work = sys.argv[1]
    fails = []
    rms = {}
    for kind in ("aligned", "random"):
        for h in SIZES:
            f = exactTractionLadder.fields(
                os.path.join(work, "%s-%g" % (kind, h)), 1e-6)
            for t, (r, m, n) in sorted(f.items()):
                rms[kind, h, round(t*1e9)] = r
                print("%-7s h %.3f um  t %.2f ns: rms lateral strain %.3e, "
                      "largest %.3e (%d elements deeper than 1 um)"
                      % (kind, h, t*1e9, r, m, n))
    for t in (66, 70):
        a = [rms["aligned", h, t] for h in SIZES]
        if not a[0] < 3e-4:
            fails.append("aligned 0.35 um, %d ns: rms %.3e >= 3e-4"
                         % (t, a[0]))
        for i in range(2):
            p = exactTractionLadder.math.log(a[i]/a[i + 1]) \
                / exactTractionLadder.math.log(SIZES[i]/SIZES[i + 1])
            print("aligned %d ns: observed order %.2f from %g to %g um"
                  % (t, p, SIZES[i], SIZES[i + 1]))
            if not p >= 1.0:
                fails.append("aligned %d ns: order %.2f < 1 from %g to %g"
                             " um" % (t, p, SIZES[i], SIZES[i + 1]))
        for h in SIZES:
            r, al = rms["random", h, t], rms["aligned", h, t]
            if not r > 5*al:
                fails.append("random %g um, %d ns: rms %.3e not above 5 "
                             "times the aligned mesh's %.3e" % (h, t, r, al))
    _, out = exactTractionLadder.ballLadder.run(
        "1.75e-7=%s" % os.path.join(work, "aligned-0.175"),
        verify=False)
    p2 = out["p2"]
    err = p2["vm"]/p2["ref"] - 1
    b = p2["vm"]/p2["vmJ"] - 1
    print("aligned 0.175 um, r = 2 um: von Mises 1-ns peak %.4f Pa against "
          "%.4f Pa: %+.2f %%, non-uniaxial part %+.3f %%"
          % (p2["vm"], p2["ref"], 100*err, 100*b))
    if not abs(err) <= 0.03:
        fails.append("von Mises at r = 2 um %+.2f %% outside 3 %%"
                     % (100*err))
    if not abs(b) <= 0.003:
        fails.append("its non-uniaxial part %+.3f %% outside 0.3 %%"
                     % (100*b))
    for f in fails:
        print("FAIL " + f)
    if fails:
        sys.exit(1)
    print("exactTraction: ok")


if __name__ == "__main__":
    main()

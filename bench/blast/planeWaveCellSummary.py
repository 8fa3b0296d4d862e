#!/usr/bin/python3
"""Summary of planeWaveCell logs (-vonMises, -every 1e-9): during the
passage window (--window, ns) the largest lateral nodal speed, the
mass-weighted rms lateral speed (largest and time mean), the largest rms
v_z error; the peak of each region's mean element von Mises; and at a few
times after it the lateral speeds and the region means of the von Mises
(absolute and over their peaks) and of |rz| shear stress (exact: 0). Not
a test (docs/results/blast3D.md, "The von Mises at rest in 3D").

    bench/blast/planeWaveCellSummary.py LOG ... [--window 55 90]
"""
import argparse
import re
from neuronFsi import script  # noqa: E402
script.guard()  # an input's error: one line, exit 1 (adv53 u12)

ROW = re.compile(r"t +([\d.]+) ns +error rms (\S+) m/s +max (\S+) m/s .* "
                 r"lateral max (\S+) m/s +rms (\S+) m/s +mass-weighted rms "
                 r"(\S+) m/s")
VM = re.compile(r" +mean von Mises \[Pa\]: nucleus (\S+) cytoplasm (\S+) "
                r"membrane (\S+) +mean \|rz shear stress\| \[Pa\]: nucleus "
                r"(\S+) cytoplasm (\S+) membrane (\S+)")


def main():
    a = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    a.add_argument("logs", nargs="+")
    a.add_argument("--window", nargs=2, type=float, default=[55, 90])
    a.add_argument("--times", nargs="+", type=float,
                   default=[90, 100, 120, 150])
    o = a.parse_args()
    for path in o.logs:
        rows, vm, rz = [], [], []
        with open(path) as f:
            head = f.readline().split(",")[0]
            for line in f:
                m = ROW.match(line)
                if m:
                    rows.append([float(x) for x in m.groups()])
                m = VM.match(line)
                if m:
                    v = [float(x) for x in m.groups()]
                    vm.append(v[:3])
                    rz.append(v[3:])
        if not rows or len(vm) != len(rows):
            raise SystemExit("%s: not a planeWaveCell -vonMises log" % path)
        w = [r for r in rows if o.window[0] <= r[0] <= o.window[1]]
        print("%s (%s)" % (path, head))
        print("  passage %g-%g ns: lateral speed largest %.2f m/s, "
              "mass-weighted rms largest %.3f m/s, time mean %.3f m/s; "
              "v_z error rms largest %.2f m/s"
              % (o.window[0], o.window[1], max(r[3] for r in w),
                 max(r[5] for r in w), sum(r[5] for r in w)/len(w),
                 max(r[1] for r in w)))
        pk = [max(v[i] for v in vm) for i in range(3)]
        print("  peak of the mean element von Mises: nucleus %.2f, "
              "cytoplasm %.2f, membrane %.2f Pa" % tuple(pk))
        for t in o.times:
            for r, v, s in zip(rows, vm, rz):
                if abs(r[0] - t) < 0.01:
                    print("  %5.1f ns: lateral mass-weighted rms %.3g m/s "
                          "(largest %.3g); von Mises %.3g / %.3g / %.3g Pa "
                          "(%.3f / %.3f / %.3f of the peak); |rz| %.3g / "
                          "%.3g / %.3g Pa" % (t, r[5], r[3], *v,
                                              *[v[i]/pk[i] for i in range(3)],
                                              *s))


if __name__ == "__main__":
    main()

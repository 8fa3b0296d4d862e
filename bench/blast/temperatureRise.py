#!/usr/bin/python3
"""The solid's temperature rise per region over the writes of a blast case
(issue 17 item 8, the paper's Fig. 9; docs/results/blastPlaneWave.md,
"Item 8 at the default sizes"; not a test).

    bench/blast/temperatureRise.py CASE [CASE ...]

CASE: a blast case with solid/solid.h5. Per region with an energy
equation (nucleus, cytoplasm; the membrane's quadratic law has none: 0):
the largest element temperature rise over the writes and its time, the
largest at the write nearest 65.5 ns (the paper's figure) and at the last
write.
"""
import argparse

import numpy as np

from neuronFsi import script  # noqa: E402
# an input's error is one line, not a traceback (adv52 p18)
script.guard()
from neuronFsi import bench
from neuronFsi.solidResults import SolidResults

NAMES = {0: "nucleus", 1: "cytoplasm"}   # bench/blast/interfaceProfile.py


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("case", nargs="+")
    a = bench.parse(ap)
    print("# case region maxAnyWrite[K] atTime[ns] at65.5ns[K] lastWrite[K] "
          "lastTime[ns]")
    for case in a.case:
        with SolidResults(case + "/solid/solid.h5") as s:
            region = s.mesh("region")
            steps = s.steps()
            t = np.array([s.time(k) for k in steps])
            dT = np.array([[s.field(k, "temperatureRise")[region == r].max()
                            for r in NAMES] for k in steps])
            k65 = int(np.argmin(np.abs(t - 65.5e-9)))
            for j, name in enumerate(NAMES.values()):
                i = int(np.argmax(dT[:, j]))
                print("%s %s %.4f %.2f %.4f %.4f %.2f" % (
                    case, name, dT[i, j], t[i]*1e9, dT[k65, j], dT[-1, j],
                    t[-1]*1e9))


if __name__ == "__main__":
    bench.main(main)

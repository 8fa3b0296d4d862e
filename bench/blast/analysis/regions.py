#!/usr/bin/python3
"""Per solid region (its index in mesh/region): the element count and the
range of pressure and von Mises at the write nearest t [ns].
usage: regions.py solid/solid.h5 t_ns"""
import sys
import numpy as np

from neuronFsi import script  # noqa: E402
script.guard()  # an input's error: one line, exit 1 (adv53 u12)
script.arguments(2, "solid.h5 t_ns")
from neuronFsi.solidResults import SolidResults

with SolidResults(sys.argv[1]) as f:
    k = f.nearest(float(sys.argv[2])*1e-9)
    reg = f.mesh('region')
    vm, p = f.field(k, 'vonMises').ravel(), f.field(k, 'pressure').ravel()
    print(f"write at {f.time(k)*1e9:.2f} ns")
    for i in np.unique(reg):
        w = reg == i
        print(f"region {i}: {w.sum()} elements, von Mises {vm[w].min():.1f}-"
              f"{vm[w].max():.1f} Pa, pressure {p[w].min()/1e6:.1f}-"
              f"{p[w].max()/1e6:.1f} MPa")

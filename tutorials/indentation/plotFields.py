#!/usr/bin/python3
"""Pressure and von Mises fields of an indentation case at a peak.

usage: plotFields.py <case> [label]     (label: a line of peaks.dat,
                                         default C1,i, the first peak)

Reads <case>/postProcessing/indentation/{peaks.dat,solid.h5} and writes
<case>/fields_<label>.png: the r-z section (deformed) coloured by the
element pressure and von Mises stress [Pa], with the region boundaries,
like the paper's Figs. 7 and 8 (it shows C2,ii at 26.88 s), and prints
the extremes per region.
"""
import os
import sys

import numpy as np
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
from matplotlib.collections import PolyCollection

from neuronFsi import msh, postProcessing
from neuronFsi.solidResults import SolidResults

case = sys.argv[1]
label = sys.argv[2] if len(sys.argv) > 2 else "C1,i"
out = os.path.join(case, "postProcessing", "indentation")
table = postProcessing.readTable(os.path.join(out, "peaks.dat"))
peaks = dict(zip(table.column("label"), table.column("time")))
if label not in peaks:
    sys.exit("plotFields: no peak '%s' in %s (have: %s)"
             % (label, os.path.join(out, "peaks.dat"), " ".join(peaks)))
t = peaks[label]
with SolidResults(os.path.join(out, "solid.h5")) as f:
    X = f.mesh("coordinates")
    conn = f.mesh("connectivity")
    region = f.mesh("region")
    k = f.nearest(t)
    if abs(f.time(k) - t) > 1e-6*max(1, t):
        sys.exit("plotFields: no field step at t = %g s in solid.h5" % t)
    u = f.field(k, "displacement")
    p = f.field(k, "pressure")
    vm = f.field(k, "vonMises")


names = msh.physicalNames(os.path.join(case, "constant", "cell.msh"), 2)
x = (X + u)[:, :2]*1e6
polys = [x[c] for c in conn]
fig, axes = plt.subplots(1, 2, figsize=(11, 4.2))
for ax, v, name in zip(axes, (p, vm), ("pressure [Pa]", "von Mises [Pa]")):
    pc = PolyCollection(polys, array=v, cmap="viridis", edgecolors="none")
    ax.add_collection(pc)
    for r in np.unique(region):
        # region outlines: edges used by one element of the region only
        edges = {}
        for c in conn[region == r]:
            for a, b in zip(c, np.roll(c, -1)):
                e = (min(a, b), max(a, b))
                edges[e] = edges.get(e, 0) + 1
        for (a, b), n in edges.items():
            if n == 1:
                ax.plot(x[[a, b], 0], x[[a, b], 1], "w-", lw=0.4)
    ax.set_aspect("equal")
    ax.autoscale_view()
    ax.set_xlabel("r [um]")
    ax.set_ylabel("z [um]")
    ax.set_title("%s at %s (t = %.2f s)" % (name, label, t))
    fig.colorbar(pc, ax=ax, shrink=0.8)
fig.tight_layout()
png = os.path.join(case, "fields_%s.png" % label.replace(",", "_"))
fig.savefig(png, dpi=130)
for r in np.unique(region):
    m = region == r
    n = names[r] if r < len(names) else "region %d" % r
    print("%-10s pressure %9.2f .. %9.2f Pa, von Mises max %9.2f Pa"
          % (n, p[m].min(), p[m].max(), vm[m].max()))
print("Written", png)

#!/usr/bin/python3
"""Peaks of the solid probes of blast runs, one row per case and probe:
largest pressure [MPa] and von Mises [Pa], most negative longitudinal
strain ln|F e_z| [-] over the whole run, and the probe's header line (its
point, region and element). Used for the probe table of
docs/results/blast.md (the same probes on a ladder of solid meshes).
usage: probePeaks.py case [case ...]"""
import sys

import numpy as np

from neuronFsi import script  # noqa: E402
script.guard()  # an input's error: one line, exit 1 (fix19k: every script)
from neuronFsi import postProcessing

log = "solidProbes/solidProbes.dat"
print(f"{'case':>40s} {'probe':>5s} {'pMax[MPa]':>10s} {'vMmax[Pa]':>10s} "
      f"{'strainZmin[-]':>14s}  where")
for case in sys.argv[1:]:
    names = postProcessing.names(case, log)
    d = postProcessing.series(case, log)
    where = [h for h in postProcessing.header(case, log)
             if h.startswith("probe ")]
    for i, w in enumerate(where):
        col = {n: d[:, names.index(n)] for n in
               (f"p{i}", f"vonMises{i}", f"strainZ{i}")}
        print(f"{case[-40:]:>40s} {i:5d} {col[f'p{i}'].max()/1e6:10.4f} "
              f"{col[f'vonMises{i}'].max():10.4f} "
              f"{np.min(col[f'strainZ{i}']):14.6f}  {w}")

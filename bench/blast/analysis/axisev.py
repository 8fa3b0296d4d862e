#!/usr/bin/python3
"""Axis column vs its neighbours over time: pressure of the axis element
(r < 0.25 um) and the mean of the next ring (0.4 < r < 0.9 um) per z layer
above z0; vz of axis nodes."""
import sys, numpy as np
from neuronFsi import script  # noqa: E402
script.guard()  # an input's error: one line, exit 1 (adv53 u12)
script.arguments(1, "solid.h5 [z0 [RA]]")
from neuronFsi.solidResults import SolidResults
f = SolidResults(sys.argv[1])
X = f.mesh('coordinates'); conn = f.mesh('connectivity')
C = X[conn].mean(axis=1); r = np.hypot(C[:, 0], C[:, 1])
z0 = float(sys.argv[2]) if len(sys.argv) > 2 else 6.0e-6
RA = float(sys.argv[3]) if len(sys.argv) > 3 else 0.25e-6
ax = np.where((r < RA) & (C[:, 2] > z0))[0]
ax = ax[np.argsort(-C[ax, 2])]
an = np.where((np.hypot(X[:, 0], X[:, 1]) < 1e-9) & (X[:, 2] > z0))[0]
an = an[np.argsort(-X[an, 2])]
print('axis elements z [um]:', ' '.join('%.2f' % (C[e, 2]*1e6) for e in ax))
print('axis nodes z [um]:   ', ' '.join('%.2f' % (X[a, 2]*1e6) for a in an))
for s in f.steps():
    t = f.time(s)*1e9
    if t < 50: continue
    p = f.field(s, 'pressure').ravel()/1e6; v = f.field(s, 'velocity')
    dp = []
    for e in ax:
        ring = np.where((r > 1.6*RA) & (r < 3.6*RA)
                        & (abs(C[:, 2] - C[e, 2]) < 0.05e-6))[0]
        dp.append('%+.2f' % (p[e] - p[ring].mean()))
    print('%6.2f ns  p_axis %6.2f MPa  dp(axis-ring) [MPa] %s  | vz axis [m/s] %s'
          % (t, p[ax[0]], ' '.join(dp), ' '.join('%+.1f' % v[a, 2] for a in an)))

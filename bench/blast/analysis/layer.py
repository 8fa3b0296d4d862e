#!/usr/bin/python3
"""vz of the nodes at the height of each axis node (|dz| < 0.03 um, r < Rmax)
by radius, at the given times."""
import sys, numpy as np
from neuronFsi import script  # noqa: E402
script.guard()  # an input's error: one line, exit 1 (adv53 u12)
script.arguments(1, "solid.h5 [t ...]")
from neuronFsi.solidResults import SolidResults
f = SolidResults(sys.argv[1])
X = f.mesh('coordinates')
R = np.hypot(X[:, 0], X[:, 1])
an = np.where((R < 1e-9) & (X[:, 2] > 6.5e-6))[0]
an = an[np.argsort(-X[an, 2])]
want = [float(a) for a in sys.argv[2:]]
for s in f.steps():
    t = f.time(s)*1e9
    if not any(abs(t - w) < 0.1 for w in want): continue
    v = f.field(s, 'velocity'); u = f.field(s, 'displacement')
    print('--- %.2f ns' % t)
    for a in an:
        n = np.where((abs(X[:, 2] - X[a, 2]) < 0.03e-6) & (R < 2.5e-6))[0]
        n = n[np.argsort(R[n])]
        print('  z %.2f: ' % (X[a, 2]*1e6) + ' '.join(
            '%.2f:%+.1f' % (R[k]*1e6, v[k, 2]) for k in n[:10]))

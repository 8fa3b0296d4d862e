#!/usr/bin/python3
"""Membrane elements near (r, z): vM, J and the nodal velocities (radial,
vertical) of their nodes, over time."""
import sys, numpy as np
from neuronFsi import script  # noqa: E402
script.guard()  # an input's error: one line, exit 1 (adv53 u12)
script.arguments(3, "solid.h5 r z")
from neuronFsi.solidResults import SolidResults
f = SolidResults(sys.argv[1])
R0, Z0 = float(sys.argv[2]), float(sys.argv[3])
X = f.mesh('coordinates'); conn = f.mesh('connectivity'); reg = f.mesh('region')
C = X[conn].mean(axis=1); r = np.hypot(C[:, 0], C[:, 1])
d = np.hypot(r - R0, C[:, 2] - Z0) + 1e3*(reg != 2)
e = np.argmin(d)
print('element', e, 'centroid r %.2f z %.2f um' % (r[e]*1e6, C[e, 2]*1e6))
nodes = conn[e]
for s in f.steps():
    t = f.time(s)*1e9
    if t < 55: continue
    v = f.field(s, 'velocity'); u = f.field(s, 'displacement')
    rr = np.hypot(X[nodes, 0], X[nodes, 1])
    vr = (v[nodes, 0]*X[nodes, 0] + v[nodes, 1]*X[nodes, 1])/rr
    ur = (u[nodes, 0]*X[nodes, 0] + u[nodes, 1]*X[nodes, 1])/rr
    print('%6.2f ns vM %7.0f Pa J %.4f | node r,z [um]: ur [nm] uz [nm]: %s' % (
        t, f.field(s, 'vonMises').ravel()[e], f.field(s, 'J').ravel()[e], ' '.join('(%.2f,%.2f):%.0f,%.0f' % (
        rr[k]*1e6, X[nodes[k], 2]*1e6, ur[k]*1e9, u[nodes[k], 2]*1e9) for k in range(8))))

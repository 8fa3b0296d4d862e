#!/usr/bin/python3
"""Fluid interface faces near the pole from a legacy ASCII VTK patch file:
centroid r, z, area, p."""
import sys, numpy as np
from neuronFsi import script  # noqa: E402
script.guard()  # an input's error: one line, exit 1 (adv53 u12)
script.arguments(1, "patch.vtk [Rmax]")
L = open(sys.argv[1]).read().split('\n')
i = next(k for k, l in enumerate(L) if l.startswith('POINTS'))
n = int(L[i].split()[1]); vals = []
k = i + 1
while len(vals) < 3*n:
    vals += L[k].split(); k += 1
P = np.array(vals, float).reshape(n, 3)
i = next(k for k, l in enumerate(L) if l.startswith('POLYGONS'))
nf = int(L[i].split()[1]); tot = int(L[i].split()[2]); faces = []
tok = []; k = i + 1
while len(tok) < tot:
    tok += L[k].split(); k += 1
tok = list(map(int, tok)); j = 0
while j < len(tok):
    faces.append(tok[j+1:j+1+tok[j]]); j += 1 + tok[j]
i = next(k for k, l in enumerate(L) if l.startswith('p 1') and int(l.split()[2]) == nf)
vals = []; k = i + 1
while len(vals) < nf:
    vals += L[k].split(); k += 1
p = np.array(vals, float)
Rmax = float(sys.argv[2]) if len(sys.argv) > 2 else 1.5e-6
rows = []
for fi, fc in enumerate(faces):
    x = P[fc]; c = x.mean(0)
    A = 0.5*np.linalg.norm(np.cross(x[1]-x[0], x[2]-x[0]))
    r = np.hypot(c[0], c[1])
    if r < Rmax: rows.append((r, c[2], A, p[fi], np.degrees(np.arctan2(c[1], c[0]))))
for r, z, A, pp, ph in sorted(rows):
    print('r %.3f um z %.3f um phi %3.0f A %.3f um2 p %.3f MPa' % (r*1e6, z*1e6, ph, A*1e12, pp/1e6))

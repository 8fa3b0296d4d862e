#!/usr/bin/python3
import sys, numpy as np
from neuronFsi import script  # noqa: E402
script.guard()  # an input's error: one line, exit 1 (adv53 u12)
script.arguments(2, "solid.h5 t")
from neuronFsi.solidResults import SolidResults
f = SolidResults(sys.argv[1])
X = f.mesh('coordinates'); conn = f.mesh('connectivity'); reg = f.mesh('region')
C = X[conn].mean(axis=1)
for s in f.steps():
    t = f.time(s)*1e9
    if t < float(sys.argv[2]): continue
    vm = f.field(s, 'vonMises').ravel(); J = f.field(s, 'J').ravel()
    k = np.argsort(-vm)[:4]
    print('%6.2f ns ' % t + ' | '.join('e%d r%d (%.2f,%.2f,%.2f) vM %.0f Pa J %.4f' % (
        e, reg[e], C[e,0]*1e6, C[e,1]*1e6, C[e,2]*1e6, vm[e], J[e]) for e in k))

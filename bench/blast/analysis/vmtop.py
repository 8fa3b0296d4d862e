#!/usr/bin/python3
import sys, h5py, numpy as np
f = h5py.File(sys.argv[1], 'r')
X = f['mesh/coordinates'][:]; conn = f['mesh/connectivity'][:]; reg = f['mesh/region'][:]
C = X[conn].mean(axis=1)
for s in sorted(f['steps'].keys(), key=int):
    g = f['steps'][s]; t = g.attrs['time']*1e9
    if t < float(sys.argv[2]): continue
    vm = g['vonMises'][:].ravel(); J = g['J'][:].ravel()
    k = np.argsort(-vm)[:4]
    print('%6.2f ns ' % t + ' | '.join('e%d r%d (%.2f,%.2f,%.2f) vM %.0f Pa J %.4f' % (
        e, reg[e], C[e,0]*1e6, C[e,1]*1e6, C[e,2]*1e6, vm[e], J[e]) for e in k))

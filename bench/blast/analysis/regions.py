#!/usr/bin/python3
"""Per solid region (its index in mesh/region): the element count and the
range of pressure and von Mises at the write nearest t [ns].
usage: regions.py solid/solid.h5 t_ns"""
import sys
import h5py
import numpy as np

with h5py.File(sys.argv[1], 'r') as f:
    s = f['steps']
    k = min(s, key=lambda k: abs(s[k].attrs['time'] - float(sys.argv[2])*1e-9))
    reg = f['mesh/region'][:]
    vm, p = s[k]['vonMises'][:].ravel(), s[k]['pressure'][:].ravel()
    print(f"write at {s[k].attrs['time']*1e9:.2f} ns")
    for i in np.unique(reg):
        w = reg == i
        print(f"region {i}: {w.sum()} elements, von Mises {vm[w].min():.1f}-"
              f"{vm[w].max():.1f} Pa, pressure {p[w].min()/1e6:.1f}-"
              f"{p[w].max()/1e6:.1f} MPa")

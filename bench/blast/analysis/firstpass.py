#!/usr/bin/python3
"""First-passage (t <= T) probe and interface maxima of a blast case."""
import sys, numpy as np
from neuronFsi import script  # noqa: E402
script.guard()  # an input's error: one line, exit 1 (adv53 u12)
script.arguments(1, "CASE [T]")
from neuronFsi.postProcessing import series
case = sys.argv[1]; T = float(sys.argv[2]) if len(sys.argv) > 2 else 90e-9
d = series(case, 'solidProbes/solidProbes.dat')
d = d[d[:, 0] <= T]
t = d[:, 0]
p, vm = d[:, 1], d[:, 2]
base = 1 + 5*((d.shape[1] - 1)//7)    # strain_z, rate of probe 0
sz, srz = d[:, base], d[:, base + 1]
i, j = np.argmax(p), np.argmax(vm)
print('%s: to %.2f ns; probe p max %.2f MPa at %.2f ns, vM max %.2f Pa at %.2f ns, '
      'strain_z min %.4f, strain rate min/max %.3g / %.3g 1/s, dT max %.3f K' % (
      case, t[-1]*1e9, p[i]/1e6, t[i]*1e9, vm[j], t[j]*1e9, sz.min(), srz.min(), srz.max(),
      d[:, 5].max()))
m = series(case, 'solidInterfaces/interfaceMaxima.dat')
m = m[m[:, 0] <= T]
print('   interface maxima: membrane-cytoplasm %.2f MPa / %.0f Pa, cytoplasm-nucleus %.2f MPa / %.0f Pa'
      % (m[:, 1].max()/1e6, m[:, 2].max(), m[:, 3].max()/1e6, m[:, 4].max()))
c = series(case, 'fsi/coupling.dat')
c = c[c[:, 0] <= T]
print('   steps %d, passes mean %.2f max %d, unconverged %d' % (len(c), c[:, 2].mean(), c[:, 2].max(), (c[:, 4] == 0).sum()))

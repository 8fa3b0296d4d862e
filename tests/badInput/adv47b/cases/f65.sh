#!/bin/bash
# f65 (class 1, the 3D quarter's restart in the pulse; f17's note): q (30 um box, the pulse at the cell from about 15 ns) continued on 2 ranks 2e-9 -> 18e-9 unbroken (A) and 2e-9 -> 15e-9, then 15e-9 -> 18e-9 (B): B's logs equal A's to round-off (per column: max |B - A| against max |A|). The axisymmetric restart is bitwise (f05); a difference beyond round-off here would be a restart that changes the result.
. "$(dirname "$0")/../lib.sh"
q; mv $W/q $W/A; cd $W/A; latest; qEnd 18e-9; tryt 900 "A: 2 -> 18 ns unbroken" mpirun -np 2 cellBlastFoam -parallel
q; latest; qEnd 15e-9; tryt 900 "B: 2 -> 15 ns" mpirun -np 2 cellBlastFoam -parallel; qEnd 18e-9; tryt 900 "B: 15 -> 18 ns" mpirun -np 2 cellBlastFoam -parallel; cont
PYTHONPATH=$ROOT/src/python /usr/bin/python3 - $W/A <<'P'
import sys, numpy as np
from neuronFsi.postProcessing import series
for log in ("fsi/coupling.dat", "solidProbes/solidProbes.dat", "solidInterfaces/interfaceMaxima.dat", "fluidProbes/p"):
    a = np.asarray(series(sys.argv[1], log), float); b = np.asarray(series(".", log), float)
    n = min(len(a), len(b)); d = np.abs(a[:n] - b[:n]).max(axis=0)[1:]; m = np.abs(a[:n]).max(axis=0)[1:]
    r = d / np.where(m > 0, m, 1); i = int(np.argmax(r))
    print("   %s: %d/%d rows, times %s; largest column difference %.2g of its max |value| (column %d: %.3g of %.3g)" % (log.split('/')[0], len(b), len(a), "same" if np.array_equal(a[:n, 0], b[:n, 0]) else "DIFFER", r[i], i + 1, d[i], m[i]))
P

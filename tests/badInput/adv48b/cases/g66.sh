#!/bin/bash
# g66 (class 1, the inflow's state written for restarts) ibd (planeWaveInflow top, finished at 2e-09): in 2e-09/p the top patch's ambientTemperature (the ambient state taken at the start, 293.15 K) set to 300 and, separately, ambientPressure 0 set to 1e5; restart to 3e-9 (a) as it is (refused as an edited file), (b) with -acceptEdited: refused naming 2e-09/p, boundaryField/top, the entry and both values (the record compares p's boundary conditions, and the wave was computed for the other state); never continued with another ambient state.
. "$(dirname "$0")/../lib.sh"
ibd; latest; iEnd 3e-9; cp 2e-09/p ../p0
for e in "ambientTemperature 300" "ambientPressure 100000"; do cp ../p0 2e-09/p; /usr/bin/python3 - 2e-09/p "$e" <<'P'
import sys, re
p, e = sys.argv[1:3]; k, v = e.split(); b = open(p, 'rb').read()
n, c = re.subn((r'(\n\s+%s\s+)[-+0-9.eE]+;' % k).encode(), lambda m: m.group(1) + v.encode() + b';', b, count=1); open(p, 'wb').write(n); print("   %s set in 2e-09/p: %d" % (e, c))
P
  sums > ../s0; tryt 200 "(a) $e" cellBlastFoam; echo "   changed: $(changed ../s0)"; rm -rf 3e-09; tryt 200 "(b) $e, -acceptEdited" cellBlastFoam -acceptEdited; cont; echo "   changed: $(changed ../s0)"; rm -rf 3e-09; done

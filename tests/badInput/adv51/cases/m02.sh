#!/bin/bash
# CASETIMEOUT=600
# m02 (fix19g's estimates with the traps held and the cell's floor, adv50a k11 / cellDiameter 1e-200, varied): cellMesh on
# the r-z cell (mdir) and quarter3D (qm): (a) each size (nucleusSize, cytoplasmSize, membraneSize, contactSize, azimuthSize
# in 3D) at the reader's edges 1e-300 and 1.0000000000000001e-300, the smallest normal 2.2250738585072014e-308, a
# subnormal 4.9e-324, 0, -0, -1e-200, nan, inf, 1e400, two numbers; (b) cellDiameter and cellHeight at the new floor 1e-07
# (excluded), 1e-07 + 1 ulp (1.0000000000000001e-07) and the top 0.001, 0.001 + 1 ulp, and membraneThickness at its edge
# against a 1e-07 cell; (c) the hex water's nearSize/farSize tiny (1e-200) in the quarter. Each refused rc 1 naming the
# entry, its value as written and its range (or the count "beyond any count" with maxElements), or meshed; never a
# signal, never a mesh written after a refusal.
. "$(dirname "$0")/../lib.sh"
res() { echo "   sig: $(sig) | cell.msh: $(ls constant/cell.msh 2>/dev/null)"; }
for k in nucleusSize cytoplasmSize membraneSize contactSize; do for v in 1e-300 1.0000000000000001e-300 2.2250738585072014e-308 4.9e-324 0 -0 -1e-200 nan inf 1e400 "1e-7 1e-7"; do
  mdir; mset $k "$v"; echo "(a) r-z $k $v:"; (ulimit -v 3000000; cm "" 60); res; done; done
for v in 1e-300 2.2250738585072014e-308 4.9e-324 -0 nan 1e400; do qm; mset azimuthSize "$v"; echo "(a) quarter3D azimuthSize $v:"; (ulimit -v 3000000; cm "" 60); res; done
for k in cellDiameter cellHeight; do for v in 1e-07 1.0000000000000001e-07 9.9999999999999995e-08 0.001 0.0010000000000000002 1e-200; do
  mdir; mset $k "$v"; echo "(b) r-z $k $v:"; (ulimit -v 3000000; cm "" 60); res; done; done
mdir; mset cellDiameter 1.0000000000000001e-07; mset cellHeight 1.0000000000000001e-07; mset membraneThickness 1e-8; mset nucleusSize 1e-8; mset cytoplasmSize 1e-8; mset membraneSize 1e-8; echo "(b) r-z cell 1e-07+ulp both, membrane 1e-8, sizes 1e-8:"; (ulimit -v 3000000; cm "" 60); res
for k in nearSize farSize growthDistance boxSize; do for v in 1e-200 4.9e-324; do qm "$k $v;"; echo "(c) quarter3D fluid $k $v:"; (ulimit -v 3000000; cm "" 60); res; done; done
for k in axialSize lateralSize; do qm "" "$k 1e-200;"; echo "(c) quarter3D hexCoeffs $k 1e-200:"; (ulimit -v 3000000; cm "" 60); res; done

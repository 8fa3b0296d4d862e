#!/bin/bash
# b42 (class 1+4, a decomposed blast): 2 ranks to 2 ns; (a) processor1's constant/polyMesh/points with one coordinate changed in its 7th digit, restart -parallel to 3 ns: refused naming the rank's mesh file, nothing changed; (b) points back, restart on 3 ranks (mpirun -np 3) of the 2-processor case: an error naming the decomposition, nothing changed; (c) reconstructPar, solidToFoam, foamToVTK and foamToVTK -region solid on the outputs: rc 0, files written?
. "$(dirname "$0")/../lib.sh"
pblastDone; latest; blastEnd 3e-9 1e-9; F=processor1/constant/polyMesh/points; cp $F ../points.orig; sums > ../before
/usr/bin/python3 - $F <<'P'
import re, sys
t = open(sys.argv[1]).read(); m = re.search(r'\n\((-?[0-9.e+-]+) (-?[0-9.e+-]+) (-?[0-9.e+-]+)\)\n', t[t.index('(\n'):]); off = t.index('(\n')
a, b = m.start(1) + off, m.end(1) + off; v = float(t[a:b]); nv = repr(v * (1 + 3e-7) + (1e-12 if v == 0 else 0))
open(sys.argv[1], 'w').write(t[:a] + nv + t[b:]); print("   changed", t[a:b], "->", nv)
P
tryf "(a) rank 1's points changed" mpirun -np 2 cellBlastFoam -parallel; nochange ../before; cp ../points.orig $F
tryf "(b) 3 ranks" mpirun -np 3 cellBlastFoam -parallel; nochange ../before
reconstructPar > log.rec 2>&1; echo "   reconstructPar rc=$?"; solidToFoam solid/solid.h5 > log.s2f 2>&1; echo "   solidToFoam rc=$?"; foamToVTK > log.vtk 2>&1; echo "   foamToVTK rc=$? $(grep -a -m1 -i 'error' log.vtk)"; foamToVTK -region solid > log.vtk2 2>&1; echo "   foamToVTK -region solid rc=$? $(grep -a -m1 -i 'error' log.vtk2); VTK: $(find VTK -name '*.vt*' | wc -l) files"

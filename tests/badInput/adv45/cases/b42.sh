#!/bin/bash
# b42 (class 1+4, a decomposed blast): 2 ranks to 2 ns; (a) processor1's constant/polyMesh/points with one coordinate changed (its lowest bits: the file is binary), restart -parallel to 3 ns: refused naming the rank's mesh file, nothing changed; (b) points back, restart on 3 ranks (mpirun -np 3) of the 2-processor case: an error naming the decomposition, nothing changed; (c) reconstructPar, solidToFoam, foamToVTK and foamToVTK -region solid on the outputs: rc 0, files written?
. "$(dirname "$0")/../lib.sh"
pblastDone; latest; blastEnd 3e-9 1e-9; F=processor1/constant/polyMesh/points; cp $F ../points.orig; sums > ../before
/usr/bin/python3 - $F <<'P'
import sys
b = bytearray(open(sys.argv[1], 'rb').read()); i = b.index(b'\n(', b.index(b'FoamFile')) + 2
if b'format      binary' in b or b'format binary' in b: o = i + 8 * 4; b[o] ^= 1; how = "binary: the lowest byte of the 5th double flipped (a change of about 1e-16 relative)"
else:
    import re; t = b.decode(); m = re.search(r'\((-?[0-9.e+-]+) ', t[i:]); a, e = i + m.start(1), i + m.end(1); v = float(t[a:e]); t = t[:a] + repr(v * (1 + 3e-7) + (1e-12 if v == 0 else 0)) + t[e:]; b = bytearray(t.encode()); how = "ascii: a coordinate x (1 + 3e-7)"
open(sys.argv[1], 'wb').write(b); print("   changed", how)
P
tryf "(a) rank 1's points changed" mpirun -np 2 cellBlastFoam -parallel; nochange ../before; cp ../points.orig $F
tryf "(b) 3 ranks" mpirun -np 3 cellBlastFoam -parallel; nochange ../before
reconstructPar > log.rec 2>&1; echo "   reconstructPar rc=$?"; solidToFoam solid/solid.h5 > log.s2f 2>&1; echo "   solidToFoam rc=$?"; foamToVTK > log.vtk 2>&1; echo "   foamToVTK rc=$? $(grep -a -m1 -i 'error' log.vtk)"; foamToVTK -region solid > log.vtk2 2>&1; echo "   foamToVTK -region solid rc=$? $(grep -a -m1 -i 'error' log.vtk2); VTK: $(find VTK -name '*.vt*' | wc -l) files"

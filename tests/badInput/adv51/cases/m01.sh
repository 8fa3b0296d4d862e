#!/bin/bash
# CASETIMEOUT=900
# m01 (fix19g's whole structured count, adv50a k05 (c)/adv49b i55 (d), varied beyond its example): counts beyond the label
# (int32) that only the closed form sees (the size estimate below maxElements 2147483647): (a) the r-z structured cell with
# membraneSize 1e-10 (count ~3e9 > 2^31-1) and 5e-11, maxElements 2147483647, ulimit -v 3000000; (b) quarter3D meshType
# structured, coarse sections, azimuthSize 2e-8, 5e-9, 1e-9, 2e-10 with maxElements 2147483647 (the azimuthal counts times
# the section); (c) full3D structured alike (azimuthSize 5e-9); (d) the count at maxElements 2147483647 +/-: whatever the
# count, never a wrapped or negative count, never an abort or signal, never a mesh above maxElements: refused rc 1 naming
# the whole count (digits), or a caught out-of-memory (named, exit 1).
. "$(dirname "$0")/../lib.sh"
cnt() { echo "   sig: $(sig) | abort/bad_alloc: $(grep -a -c 'bad_alloc\|terminate\|Abort\|length_error' $W/try.log) | count: $(grep -a -o -m1 'would have [-0-9.e+]* [a-z]*\|at least [-0-9.e+()a-z ]*elements\|: \(quadrilaterals\|hexahedra\) [0-9]*' $W/try.log | head -2 | tr '\n' ' ') | cell.msh: $(ls -s constant/cell.msh 2>/dev/null | cut -d' ' -f1) kB"; }
for s in 1e-10 5e-11; do mdir; mset meshType structured; mset nucleusSize 2e-6; mset cytoplasmSize 2e-6; mset membraneSize $s; mset maxElements 2147483647
  echo "(a) r-z structured membraneSize $s, maxElements 2147483647, ulimit -v 3000000:"; (ulimit -v 3000000; cm "" 400); cnt; done
for a in 2e-8 5e-9 1e-9 2e-10; do qm; mset meshType structured; mset azimuthSize $a; mset maxElements 2147483647
  echo "(b) quarter3D structured azimuthSize $a, maxElements 2147483647, ulimit -v 3000000:"; (ulimit -v 3000000; cm "" 200); cnt; done
for a in 5e-9; do qm; mset mode full3D; mset meshType structured; mset azimuthSize $a; mset maxElements 2147483647
  echo "(c) full3D structured azimuthSize $a, maxElements 2147483647, ulimit -v 3000000:"; (ulimit -v 3000000; cm "" 200); cnt; done
mdir; mset meshType structured; mset membraneSize 0.05e-6; mset maxElements 5000; cm "" 200 > /dev/null; C=$(grep -a -o -m1 'would have [0-9]*' $W/try.log | awk '{print $3}'); echo "(d) the count of membraneSize 0.05e-6: '$C'"
for m in "$((C-1)).0" "$C.0" "${C}e0" "$C" "0" "-1" "2147483647.5" "9223372036854775808"; do mdir; mset meshType structured; mset membraneSize 0.05e-6; mset maxElements $m; cm "" 200; cnt; done

#!/bin/bash
# a21 (class 4, the quarter3D tutorial's Allrun options, a tool not attacked hard): in a copy of tutorials/blast/quarter3D: -np 0, -np 4097, -np 2.5, -np 1e400, -lateral -1e-6, -far nan, -pulse 1, -refineCell 0, -npp 2 (unknown), -np 2 -np 2 (twice), -inflow abc, -tet -dz 1e-6 (exclusive), -np nproc+1 (more ranks than cores, a run): each refused before anything runs, naming the option, the value and the range; the case unchanged?
. "$(dirname "$0")/../lib.sh"
cp -r "$ROOT/tutorials/blast/quarter3D" $W/q; cd $W/q; sums > ../s
for o in "-np 0" "-np 4097" "-np 2.5" "-np 1e400" "-lateral -1e-6" "-far nan" "-pulse 1" "-refineCell 0" "-npp 2" "-np 2 -np 2" "-inflow abc" "-tet -dz 1e-6" "-np $(( $(nproc) + 1 ))"; do
  timeout -s KILL 60 ./Allrun $o > ../log.o 2>&1; rc=$?; echo "$o: rc=$rc | $(grep -a -m1 -i 'error' ../log.o | cut -c1-220)"; echo "   changed: $(changed ../s)"; ./Allclean > /dev/null 2>&1; done

#!/bin/bash
# k30 (class 4, solidProperties' probe and interface entries): short preview: interfaceProbe heightFraction 0, 1, 1.0000000000000002, -0; interfacePatchLength 0, 1e300, 1 (1 m: longer than every interface); interfacePlaces with a point of 2 components, a point nan; a named probe far outside the cell { far { point (100e-6 100e-6 0); } }; probes (); interfaces ((membrane nucleus)) (regions that share no face). Expected: each refused naming constant/solidProperties, the entry and the valid range/what is wrong, or (1 m patch, empty probe list) run and said; nothing written on refusal.
. "$(dirname "$0")/../lib.sh"
sb; F=constant/solidProperties; cp $F $W/s0
vals $F heightFraction 0 1 1.0000000000000002 -0 -- cellBlastFoam
vals $F interfacePatchLength 0 1e300 1 -- cellBlastFoam
for e in "interfacePlaces { flat (1e-6 2e-6); }" "interfacePlaces { bad (nan 0 0); }"; do cp $W/s0 $F; sed -i "/^interfacePlaces/,/^}/d" $F; echo "$e" >> $F; tryt 150 "$e" cellBlastFoam; [ -d 1e-11 ] && echo "      (ran)"; rm -rf [1-9]* solid postProcessing; done
for e in "probes { far { point (100e-6 100e-6 0); } }" "probes ();"; do cp $W/s0 $F; echo "$e" >> $F; tryt 150 "$e" cellBlastFoam; [ -d 1e-11 ] && echo "      (ran)"; rm -rf [1-9]* solid postProcessing; done
cp $W/s0 $F; sete $F interfaces "((membrane nucleus))" > /dev/null; tryt 150 "interfaces ((membrane nucleus))" cellBlastFoam; [ -d 1e-11 ] && echo "      (ran)"; cp $W/s0 $F

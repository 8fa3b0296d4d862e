#!/bin/bash
# k29 (class 4, solidProperties' viscosities valid alone not together, edges): short preview: (a) shearViscosity 0 with shearViscosityFilter yes (the guide: the filter needs shearViscosity > 0); shearViscosity 1 (outside [0, 1)), 0.9999999999999999 (inside), -0; (b) hourglassViscosityRegions { membrane 1; } (outside [0, 1)), { nucleolus 0.5; } (no such region), { membrane 0.5; membrane 0.5; }; explicitSafety 0, 1, 1.0000000000000002, 2. Expected: each refusal names constant/solidProperties, the entry, the value as written and the range; the filter without viscosity refused or warned; nothing written.
. "$(dirname "$0")/../lib.sh"
sb; F=constant/solidProperties; cp $F $W/s0
sete $F shearViscosity 0 > /dev/null; tryt 150 "(a) shearViscosity 0 + filter yes" cellBlastFoam; grep -a -i -m2 'warn\|filter' $W/try.log | cut -c1-200 | sed 's/^/   log: /'; rm -rf [1-9]* solid postProcessing; cp $W/s0 $F
vals $F shearViscosity 1 0.9999999999999999 -0 -- cellBlastFoam
for r in "membrane 1;" "nucleolus 0.5;" "membrane 0.5; membrane 0.5;"; do cp $W/s0 $F; echo "hourglassViscosityRegions { $r }" >> $F; tryt 150 "(b) hourglassViscosityRegions { $r }" cellBlastFoam; rm -rf [1-9]* solid postProcessing; done; cp $W/s0 $F
vals $F explicitSafety 0 1 1.0000000000000002 2 -- cellBlastFoam

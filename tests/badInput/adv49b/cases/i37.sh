#!/bin/bash
# i37 (class 4/SILENT, labels beyond 32 bits in cellMeshDict and the Allrun options): cellMesh with membraneLayers 4294967297
# (1 if cut), maxElements 4294967296, quarter3D fluid{hexCoeffs{maxCells 4294967297}} and fluid{maxCells 4294967297} (as
# limits: refused or taken as the value, never as 1); the preview Allrun -membraneLayers 4294967297; the quarter's Allrun
# -layers 4294967297 and -np 4294967298 (-noRun): each refused naming the entry/option, the digits and the label's largest
# value or the entry's range; never meshed with the cut value.
. "$(dirname "$0")/../lib.sh"
mdir; mset membraneLayers 4294967297; cm; mdir; mset maxElements 4294967296; cm
mdir quarter3D; sed -i 's/^\( *\)lateralSize .*/&\n\1maxCells 4294967297;/' system/cellMeshDict; cm; grep -a -i -m1 maxCells $W/try.log | cut -c1-200
prev; tryt 120 "Allrun -membraneLayers 4294967297" ./Allrun $PREV -noRun -membraneLayers 4294967297; echo "   wrote: $(ls constant/cell.msh system/*.allrun 2>/dev/null | tr '\n' ' ')"
cp -r "$ROOT/tutorials/blast/quarter3D" $W/q; cd $W/q; ./Allclean > /dev/null 2>&1
tryt 120 "quarter Allrun -layers 4294967297" ./Allrun -layers 4294967297 -noRun; tryt 120 "quarter Allrun -np 4294967298" ./Allrun -np 4294967298 -noRun; echo "   wrote: $(ls constant/cell.msh system/*.allrun processor* 2>/dev/null | tr '\n' ' ')"

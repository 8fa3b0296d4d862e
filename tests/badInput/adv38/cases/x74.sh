#!/bin/bash
# x74: the solid mesh's 'scale' at the reader's edges in the other readers: cellIndentationFoam with scale 1e300 and 1e-300, solidToFoam -> (blast solidProperties scale 1e300 after a run), cellBlastFoam with scale 1e150: a range error naming 'scale', or a floating point exception inside readGmsh (x58)?
. "$(dirname "$0")/../lib.sh"
ind; each constant/solidProperties "scale 1e300" "scale 1e-300" "scale 1e150" -- cellIndentationFoam
blastDone; sed -i 's/scale       1;/scale 1e300;/' constant/solidProperties; try "solidToFoam, scale 1e300" solidToFoam solid/solid.h5
sed -i 's/scale 1e300;/scale 1e150;/' constant/solidProperties; rm -rf [1-9]* solid postProcessing; try "cellBlastFoam scale 1e150" cellBlastFoam

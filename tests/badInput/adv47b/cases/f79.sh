#!/bin/bash
# f79 (class 5, a valid HDF5 file of the other kind): the killed indentation with (a) restart.h5 replaced by its own solid.h5 (a whole, checksummed HDF5 file that is no checkpoint), (b) solid.h5 replaced by restart.h5: each restart refused naming the file and what it is, nothing changed; never continued.
. "$(dirname "$0")/../lib.sh"
ik; d=postProcessing/indentation; cp $d/restart.h5 ../r.h5; cp $d/solid.h5 ../s.h5; cp ../s.h5 $d/restart.h5; sums > ../s0
tryt 120 "(a) restart.h5 = solid.h5" cellIndentationFoam; cont; echo "   changed: $(changed ../s0)"
cp ../r.h5 $d/restart.h5; cp ../r.h5 $d/solid.h5; sums > ../s0; tryt 120 "(b) solid.h5 = restart.h5" cellIndentationFoam; cont; echo "   changed: $(changed ../s0)"; after

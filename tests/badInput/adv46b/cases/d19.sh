#!/bin/bash
# d19 (class 2, cellBlastFoam -dry-run-write on the finished preview): "check and write using a single time step": refused over the results (they exist, no -overwrite), or writes nothing over them; DATALOSS if a time, solid.h5 or a log is changed.
. "$(dirname "$0")/../lib.sh"
bd; sums > ../s0; tryt 200 "-dry-run-write" cellBlastFoam -dry-run-write; echo "   $(tail -1 $W/try.log | cut -c1-150)"; nochange ../s0; after

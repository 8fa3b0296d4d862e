#!/bin/bash
# i27 (class 3, two serial runs launched at once by mpirun without -parallel): bd restarted to 3e-9 by `mpirun -np 2
# cellBlastFoam` (no -parallel: two serial processes on one case at once): one runs, the other is refused by the run lock
# naming the first; the case's results equal a lone restart's (cmpRef), one commit per time; mpirun's exit non-zero (one
# rank failed) or zero, but said.
. "$(dirname "$0")/../lib.sh"
bd; rs; cd $W; cp -a blast ref; cd ref; tryt 300 "lone restart" cellBlastFoam; cd $W/blast
tryt 300 "mpirun -np 2 cellBlastFoam (no -parallel)" mpirun -np 2 cellBlastFoam; grep -a -i 'lock\|in use\|refus' $W/try.log | head -3 | cut -c1-220 | sed 's/^/   /'
after; cmpRef $W/ref; marks 3e-09; echo "   markers: $(ls -a 3e-09 | grep -c writeCommitted)"

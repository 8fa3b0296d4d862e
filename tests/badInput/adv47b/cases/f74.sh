#!/bin/bash
# f74 (class 3, mpirun -np 2 on the serial solver without -parallel: two serial runs of one case at once): bd restarted to 4e-9 by mpirun -np 2 cellBlastFoam: one runs, the other is refused by the lock; mpirun may then abort the running one. Afterwards the case must be consistent: a plain restart to 4e-9 continues rc 0 and equals the clean restart (B) exactly.
. "$(dirname "$0")/../lib.sh"
bd; mv $W/blast $W/B; cd $W/B; latest; blastEnd 4e-9 1e-9; tryt 240 "B: clean restart to 4e-9" cellBlastFoam
bd; latest; blastEnd 4e-9 1e-9; tryt 240 "mpirun -np 2 cellBlastFoam (no -parallel)" mpirun -np 2 cellBlastFoam; grep -a -m2 'in use\|aborted\|Killed\|signal' $W/try.log | cut -c1-200; after; ls -d .*incomplete* *incomplete* 2>/dev/null
tryt 240 "plain restart after it" cellBlastFoam; cont; after; cmpRef $W/B

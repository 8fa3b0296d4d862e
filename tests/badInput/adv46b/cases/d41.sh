#!/bin/bash
# d41 (class 4+3, a decomposed blast case with processor1 removed, and run on 3 ranks): mpirun -np 2 -parallel, then -np 3: each a clear error (missing processor directory, rank count), no hang, no crash trace.
. "$(dirname "$0")/../lib.sh"
pblast; mv processor1 ../p1; tryt 90 "(a) processor1 missing" mpirun --allow-run-as-root --oversubscribe -np 2 cellBlastFoam -parallel; mv ../p1 processor1
tryt 90 "(b) -np 3 on 2 processors" mpirun --allow-run-as-root --oversubscribe -np 3 cellBlastFoam -parallel; ls

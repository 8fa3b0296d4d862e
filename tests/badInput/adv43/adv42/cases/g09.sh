#!/bin/bash
# g09 (class 2, user files in processor*/): 2 ranks finished to 2 ns; the user's processor0/notes.txt, processor1/2e-09/notes.txt and processor0/constant/notes.txt; (a) `mpirun -np 2 cellBlastFoam -parallel -overwrite`: refused naming processor1/2e-09/notes.txt, nothing moved? (b) that note removed, -overwrite again: runs, the other two notes kept? (c) a 2-rank restart to 3 ns with a note in processor1/2e-09/: kept?
. "$(dirname "$0")/../lib.sh"
pblastDone; echo "n0 top" > processor0/notes.txt; echo "n1 time" > processor1/2e-09/notes.txt; echo "n0 const" > processor0/constant/notes.txt; cd ..; cp -r blast c; cd blast; sums > ../s.a
tryf "(a) 2-rank -overwrite" mpirun -np 2 cellBlastFoam -parallel -overwrite; nochange ../s.a; kept "n0 top" "n1 time" "n0 const"
rm processor1/2e-09/notes.txt; tryf "(b) the time note removed, 2-rank -overwrite" mpirun -np 2 cellBlastFoam -parallel -overwrite; echo "   processor0: $(ls -a processor0 | tr '\n' ' ')"; kept "n0 top" "n0 const"
cd ../c; latest; blastEnd 3e-9 1e-9; tryf "(c) 2-rank restart to 3 ns" mpirun -np 2 cellBlastFoam -parallel; echo "   processor1: $(ls processor1 | tr '\n' ' ')"; kept "n0 top" "n1 time" "n0 const"

#!/bin/bash
# f72 (class 4, the quarter's Allrun -np above the machine's cores for a run): ./Allrun -np 3 (nproc 2) with the small sizes, not -noRun: refused before anything is meshed naming -np, 3 and nproc 2 (the header: "at most the machine's cores (nproc) for a run"); never meshed and then failing inside mpirun.
. "$(dirname "$0")/../lib.sh"
cp -r $ROOT/tutorials/blast/quarter3D $W/q3; cd $W/q3; echo "   nproc $(nproc)"
tryt 240 "Allrun -np 3" ./Allrun -box 30e-6 -h 1e-6 -dz 1e-6 -lateral 2e-6 -far 5e-6 -endTime 1e-9 -noPlots -np 3; tail -4 $W/try.log | cut -c1-250; ls | tr '\n' ' '; echo

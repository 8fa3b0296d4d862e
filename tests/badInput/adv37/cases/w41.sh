#!/bin/bash
# w41: blast preview (20 um column) to 14 ns (the pulse reaches the cell at about 11 ns): the 2-rank run (split at y = 4 um) against the serial run: equal to 1e-9 of every column (the user guide: 2 ranks equal serial to 1e-10)?
. "$(dirname "$0")/../lib.sh"
blast; blastEnd 14e-9 7e-9; cellBlastFoam > log.first 2>&1; echo "serial rc=$?"; cd ..; mv blast serial; pblast; blastEnd 14e-9 7e-9; mpirun -np 2 cellBlastFoam -parallel > log.first 2>&1; echo "2 ranks rc=$?"
/usr/bin/python3 "$ROOT/tests/blast/compareRestart.py" ../serial . --tol 1e-9 --h5 2>&1 | cut -c1-300 | tail -5

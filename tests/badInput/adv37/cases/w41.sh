#!/bin/bash
# w41: blast preview (20 um column): the 2-rank run (split at y = 4 um) against the serial run of the same case to 2 ns: equal to 1e-9 of every column (the user guide's 1e-10 claim)?
. "$(dirname "$0")/../lib.sh"
blastDone; cd ..; mv blast serial; pblastDone; /usr/bin/python3 "$ROOT/tests/blast/compareRestart.py" ../serial . --tol 1e-9 --h5 2>&1 | cut -c1-400 | tail -4

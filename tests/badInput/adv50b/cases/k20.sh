#!/bin/bash
# k20 (class 5, incidentWindow.py without what it reads): (a) bd (a finished preview on which planeWave never ran: no postProcessing/planeWave/0/reference.dat), (b) q (parallel, not reconstructed, no reference), (c) a folder that is not a case, (d) a path that does not exist. Expected: a non-zero exit with one line naming the missing file or folder and what writes it (planeWave), not a bare traceback; exit 0 with numbers never.
. "$(dirname "$0")/../lib.sh"
bd; iw .; tail -2 $W/try.log | cut -c1-200 | sed 's/^/   /'
q; iw .; tail -2 $W/try.log | cut -c1-200 | sed 's/^/   /'
mkdir -p $W/e; iw $W/e; tail -1 $W/try.log | cut -c1-200 | sed 's/^/   /'; iw $W/nothing; tail -1 $W/try.log | cut -c1-200 | sed 's/^/   /'

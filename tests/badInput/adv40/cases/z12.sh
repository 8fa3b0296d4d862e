#!/bin/bash
# z12: blast on 2 ranks to 2 ns, reconstructPar, then the user deletes processor*/ (to save space) and restarts in SERIAL from latestTime to 3 ns: continued (with a note), or refused with advice that works when followed (e.g. -acceptEdited)? solid.h5 then 3 steps?
. "$(dirname "$0")/../lib.sh"
pblastDone; reconstructPar > log.rec 2>&1 || tail -2 log.rec; rm -rf processor*; latest; blastEnd 3e-9 1e-9; echo "root times: $(ls -da [0-9]* | tr '\n' ' '); markers: $(ls [0-9]*/.writeCommitted 2>/dev/null | tr '\n' ' ')"
try "serial restart" cellBlastFoam; grep -a -i -m3 "acceptEdited\|reconstruct\|note" $W/try.log | cut -c1-250
echo "   times: $(ls -d [1-9]* | tr '\n' ' '); solid.h5 steps $(h5steps solid/solid.h5)"
if ! [ -d 3e-09 ]; then try "with -acceptEdited" cellBlastFoam -acceptEdited; echo "   times: $(ls -d [1-9]* | tr '\n' ' '); solid.h5 steps $(h5steps solid/solid.h5), xmf $(xmfsteps solid/solid.xmf)"; fi

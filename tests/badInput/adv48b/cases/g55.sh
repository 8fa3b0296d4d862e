#!/bin/bash
# g55 (class 3, foamToVTK on a run still going) bd restarted to 3e-9 in the background; foamToVTK -latestTime every 0.5 s while it runs: what it converts is a committed time (never a time carrying .writeInProgress, never a half-written field: foamToVTK is OpenFOAM's, a run can only say it); report which times were converted and whether any was being written then.
. "$(dirname "$0")/../lib.sh"
bd; rs; blastEnd 1e-8 1e-9; cellBlastFoam > ../run.log 2>&1 & p=$!; n=0
while kill -0 $p 2>/dev/null; do t=$(ls -d [0-9]* | sort -g | tail -1); w=$([ -e $t/.writeInProgress ] && echo inProgress || echo committed); timeout 60 foamToVTK -latestTime -noFunctionObjects > ../vtk.log 2>&1; r=$?; n=$((n+1)); [ $n -le 40 ] && echo "   foamToVTK rc=$r at latest $t ($w before) $(grep -a -m1 -i 'fatal\|error' ../vtk.log | cut -c1-120)"; sleep 0.5; done
wait $p; echo "   run rc=$?"; ls VTK 2>/dev/null | head -5 | tr '\n' ' '; echo; after

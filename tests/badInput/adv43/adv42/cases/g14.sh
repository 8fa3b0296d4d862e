#!/bin/bash
# g14 (class 3, two runs within milliseconds): finished blast to 2 ns; (a) two `cellBlastFoam -overwrite` started 0 ms apart; (b) `cellBlastFoam -overwrite` and `cellMesh` (which replaces constant/cell.msh) 0 ms apart; (c) two restarts to 3 ns 0 ms apart: one runs, the other refused before changing anything, naming the first? the case left consistent (solid.h5 steps = xmf steps = committed times)?
. "$(dirname "$0")/../lib.sh"
blastDone; cd ..; cp -r blast orig; cp -r blast b; cp -r blast c; cd blast
two() { ( "$@" > $W/two.1 2>&1; echo "rc=$?" >> $W/two.1 ) & ( "$@" > $W/two.2 2>&1; echo "rc=$?" >> $W/two.2 ) & wait; for i in 1 2; do echo "   run $i: $(tail -1 $W/two.$i) $(grep -a -m1 -A1 'in use\|FATAL' $W/two.$i | tr '\n' ' ' | cut -c1-220)"; done; }
state() { echo "   times $(ls -d [1-9]* 2>/dev/null | tr '\n' ' '); hidden $(ls -d .[0-9]* .*overwritten* 2>/dev/null | tr '\n' ' '); solid.h5 $(h5steps solid/solid.h5) steps, xmf $(xmfsteps solid/solid.xmf); lock $(lockOf)"; }
echo "(a) two -overwrite at once"; two cellBlastFoam -overwrite; state; sameSeries ../orig | tr '\n' ' '; echo
cd ../b; echo "(b) -overwrite and cellMesh at once"; ( cellBlastFoam -overwrite > $W/two.1 2>&1; echo "rc=$?" >> $W/two.1 ) & ( cellMesh > $W/two.2 2>&1; echo "rc=$?" >> $W/two.2 ) & wait
for i in 1 2; do echo "   $([ $i = 1 ] && echo cellBlastFoam || echo cellMesh): $(tail -1 $W/two.$i) $(grep -a -m1 -A1 'in use\|FATAL' $W/two.$i | tr '\n' ' ' | cut -c1-220)"; done; state; cmp -s constant/cell.msh ../orig/constant/cell.msh && echo "   cell.msh unchanged" || echo "   cell.msh REWRITTEN"
cd ../c; latest; blastEnd 3e-9 1e-9; echo "(c) two restarts at once"; two cellBlastFoam; state

#!/bin/bash
# CASETIMEOUT=900
# k02 (adv49a j03 / fix19f's soundSpeedMax at the edge in the other solver and in parallel: water, binary fields): the
# finished preview bd (serial) and pbd (2 ranks), startFrom latestTime, endTime 3e-9, -acceptEdited; one cell set to rest
# at rho0 (rho 1000 kg/m^3, rhoU 0) with rhoE at the Mie-Grueneisen sound-speed edge (../ulpEdge.py: 'below' c =
# 99999.99999999999 m/s, 'at' c = 1e5 m/s exactly): (a) bd cell 3 below, (b) bd cell 3 at, (c) pbd processor1 cell 3 at
# (rank 1 only), (d) pbd processor0 cell 3 at (rank 0 only: the i23 wording), (e) pbd processor1 cell 3 below (runs),
# (f) pbd processor1 rhoE's procBoundary1to0 value[0] at (a processor patch value only). 'at' refused rc 1 on every rank
# naming the cell and c (the bad rank's message printed); 'below' runs to 3e-9 or stops with a FatalError; no signal, no
# MPI error trace, no hang (120 s).
. "$(dirname "$0")/../lib.sh"
E="$(dirname "$0")/../ulpEdge.py"; read -r _ BELOW _ < <(/usr/bin/python3 $E mieGruneisen 1000 | grep '^below'); read -r _ AT _ < <(/usr/bin/python3 $E mieGruneisen 1000 | grep '^at')
echo "edge (water, rho 1000): below $BELOW, at $AT"
rest() { setb $1/rho $2 1000; fset $1/rhoU internal $2 0 0 0; setb $1/rhoE $2 $3; }
bd; rs; rm -f .runLock; cp -a . ../keep
one() { local l=$1; shift; tryt 120 "$l" "$@"; echo "   sig/stack lines: $(sig) | MPI lines: $(grep -a -c 'MPI_ERR\|ORTE_ERROR\|MPI_ABORT' $W/try.log) | times: $(ls -d [0-9]* processor1/[0-9]* 2>/dev/null | tr '\n' ' ') | End: $(grep -a -c '^End' $W/try.log)"; echo "   msg: $(msg 8)"
  echo "   lines naming a cell: $(grep -a -c 'in cell [0-9]' $W/try.log) | 'another rank': $(grep -a -c 'another rank' $W/try.log)"; }
rest 2e-09 3 $BELOW; one "(a) bd cell 3 rest, rhoE $BELOW (c below 1e5 m/s)" cellBlastFoam -acceptEdited; cd $W; rm -rf blast; cp -a keep blast; cd blast
rest 2e-09 3 $AT; one "(b) bd cell 3 rest, rhoE $AT (c = 1e5 m/s)" cellBlastFoam -acceptEdited
cd $W; rm -rf keep blast; pbd; rs; rm -f .runLock; cp -a . ../keep
again() { cd $W; rm -rf pblast; cp -a keep pblast; cd pblast; }
rest processor1/2e-09 3 $AT; one "(c) pbd processor1 cell 3 rest, rhoE $AT" mpirun -np 2 cellBlastFoam -parallel -acceptEdited; again
rest processor0/2e-09 3 $AT; one "(d) pbd processor0 cell 3 rest, rhoE $AT" mpirun -np 2 cellBlastFoam -parallel -acceptEdited; again
rest processor1/2e-09 3 $BELOW; one "(e) pbd processor1 cell 3 rest, rhoE $BELOW" mpirun -np 2 cellBlastFoam -parallel -acceptEdited; again
setbb processor1/2e-09/rhoE procBoundary1to0 0 $AT; one "(f) pbd processor1 rhoE procBoundary1to0 value[0] $AT" mpirun -np 2 cellBlastFoam -parallel -acceptEdited

#!/bin/bash
# CASETIMEOUT=900
# k03 (adv49a j04 / fix19f's launcher detection varied: a rank variable WITH a stale launcher connection variable, the other
# tools, odd values): the 2-rank preview (pblast, endTime 2e-11) and the sod tube, `-parallel` without mpirun in the
# environment of: (a) PMI_RANK=0 PMI_SIZE=2 PMI_FD=99 (fd 99 not open), (b) PMI_RANK=0 PMI_SIZE=2 PMI_PORT=localhost:1
# (nothing listening), (c) OMPI_COMM_WORLD_RANK=0 OMPI_COMM_WORLD_SIZE=2 OMPI_MCA_orte_hnp_uri=<a dead mpirun's URI form>,
# (d) PMIX_RANK=0 PMIX_SERVER_URI4=<a dead server's URI form>, (e) PMI_RANK= (empty) PMI_SIZE=2, (f) OMPI_COMM_WORLD_RANK=0
# OMPI_COMM_WORLD_SIZE=0, (g)-(l) PMI_RANK=0 PMI_SIZE=2 with the other tools: rhoRiemannFoam -parallel (sod decomposed by
# hand? not: undecomposed), cellMesh -parallel, solidToFoam -parallel, setRiemannProblem -parallel, riemannError -parallel,
# cellIndentationFoam -parallel, (m) (a)'s environment without -parallel (serial: must run). Each refused rc 1 (or, a
# stale connection, an MPI error naming it) within 60 s; never a SIGABRT/stack, never a hang; nothing changed.
. "$(dirname "$0")/../lib.sh"
pblast; short; rm -f .runLock; sums > ../s0
chk() { echo "   sig/stack lines: $(sig) | MPI lines: $(grep -a -c 'MPI_\|ORTE\|PMIX_ERR\|PMI' $W/try.log) | changed: $(changed ../s0 | tr '\n' ' ' | cut -c1-200)"; echo "   msg: $(msg 4 | cut -c1-600)"; [ "$(sig)" != 0 ] || grep -a -q 'Abort\|abort' $W/try.log && grep -a -m3 'Abort\|abort\|attempt' $W/try.log | cut -c1-200 | sed 's/^/   abort: /'; }
tryt 60 "(a) PMI_RANK=0 PMI_SIZE=2 PMI_FD=99" env PMI_RANK=0 PMI_SIZE=2 PMI_FD=99 cellBlastFoam -parallel; chk
tryt 60 "(b) PMI_RANK=0 PMI_SIZE=2 PMI_PORT=localhost:1" env PMI_RANK=0 PMI_SIZE=2 PMI_PORT=localhost:1 cellBlastFoam -parallel; chk
tryt 60 "(c) OMPI rank 0 size 2, stale orte_hnp_uri" env OMPI_COMM_WORLD_RANK=0 OMPI_COMM_WORLD_SIZE=2 "OMPI_MCA_orte_hnp_uri=1234567890.0;tcp://127.0.0.1:1" cellBlastFoam -parallel; chk
tryt 60 "(d) PMIX_RANK=0, stale PMIX_SERVER_URI4" env PMIX_RANK=0 "PMIX_SERVER_URI4=pmix-server.99999;tcp4://127.0.0.1:1" PMIX_NAMESPACE=stale cellBlastFoam -parallel; chk
tryt 60 "(e) PMI_RANK='' PMI_SIZE=2" env PMI_RANK= PMI_SIZE=2 cellBlastFoam -parallel; chk
tryt 60 "(f) OMPI_COMM_WORLD_RANK=0 OMPI_COMM_WORLD_SIZE=0" env OMPI_COMM_WORLD_RANK=0 OMPI_COMM_WORLD_SIZE=0 cellBlastFoam -parallel; chk
cd $W; sod; rm -f .runLock; sums > ../s0
tryt 60 "(g) PMI_RANK=0 PMI_SIZE=2: rhoRiemannFoam -parallel" env PMI_RANK=0 PMI_SIZE=2 rhoRiemannFoam -parallel; chk
tryt 60 "(h) PMI_RANK=0 PMI_SIZE=2: setRiemannProblem -parallel" env PMI_RANK=0 PMI_SIZE=2 setRiemannProblem -parallel; chk
tryt 60 "(i) PMI_RANK=0 PMI_SIZE=2: riemannError -parallel" env PMI_RANK=0 PMI_SIZE=2 riemannError -parallel; chk
cd $W; bd; rm -f .runLock; sums > ../s0
tryt 60 "(j) PMI_RANK=0 PMI_SIZE=2: cellMesh -parallel" env PMI_RANK=0 PMI_SIZE=2 cellMesh -parallel; chk
tryt 60 "(k) PMI_RANK=0 PMI_SIZE=2: solidToFoam -parallel solid/solid.h5" env PMI_RANK=0 PMI_SIZE=2 solidToFoam -parallel solid/solid.h5; chk
cd $W; ind; rm -f .runLock; sums > ../s0
tryt 60 "(l) PMI_RANK=0 PMI_SIZE=2: cellIndentationFoam -parallel" env PMI_RANK=0 PMI_SIZE=2 cellIndentationFoam -parallel; chk
cd $W; rm -rf pblast; pblast; short; rm -f .runLock
tryt 120 "(m) (a)'s environment, serial cellBlastFoam (undecomposed run)" env PMI_RANK=0 PMI_SIZE=2 PMI_FD=99 cellBlastFoam; echo "   sig: $(sig) | End: $(grep -a -c '^End' $W/try.log) | times: $(ls -d [0-9]* | tr '\n' ' ')"

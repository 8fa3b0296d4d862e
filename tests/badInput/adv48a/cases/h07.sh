#!/bin/bash
# CASETIMEOUT=900
# h07 (class 4, adv47b f16/f73 varied: -parallel where there is one process): the preview decomposed for 2 ranks (pblast,
# not run): (a) mpirun -np 1 cellBlastFoam -parallel, (b) cellBlastFoam -parallel (no launcher), (c) SLURM_NTASKS=2 in the
# environment (a batch job of 2 tasks) and cellBlastFoam -parallel without srun/mpirun, (d) PMI_SIZE=2 the same, (e)
# mpirun -np 3 on 2 processor directories, (f) solidToFoam -parallel, (g) cellMesh -parallel (no launcher); the sod tube
# (not decomposed): (h) mpirun -np 1 rhoRiemannFoam -parallel, (i) mpirun -np 2 rhoRiemannFoam -parallel (no processor
# directories), (j) setRiemannProblem -parallel, (k) riemannError -parallel. Each a clean error (rc != 0, no stack,
# no signal, no hang), nothing changed.
. "$(dirname "$0")/../lib.sh"
pblast; rm -f .runLock; sums > ../s0
chk() { echo "   sig/stack lines: $(sig) | changed: $(changed ../s0 | tr '\n' ' ')"; }
tryt 60 "(a) mpirun -np 1 cellBlastFoam -parallel" mpirun -np 1 cellBlastFoam -parallel; chk
tryt 60 "(b) cellBlastFoam -parallel" cellBlastFoam -parallel; chk
tryt 60 "(c) SLURM_NTASKS=2 cellBlastFoam -parallel" env SLURM_NTASKS=2 cellBlastFoam -parallel; chk; tail -4 $W/try.log | cut -c1-200
tryt 60 "(d) PMI_SIZE=2 cellBlastFoam -parallel" env PMI_SIZE=2 cellBlastFoam -parallel; chk; tail -4 $W/try.log | cut -c1-200
tryt 90 "(e) mpirun -np 3 on 2 processor dirs" mpirun --oversubscribe -np 3 cellBlastFoam -parallel; chk
tryt 60 "(f) solidToFoam -parallel" solidToFoam -parallel; chk
tryt 60 "(g) cellMesh -parallel" cellMesh -parallel; chk
cd $W; sod; sums > ../s0
tryt 60 "(h) mpirun -np 1 rhoRiemannFoam -parallel" mpirun -np 1 rhoRiemannFoam -parallel; chk
tryt 60 "(i) mpirun -np 2 rhoRiemannFoam -parallel, not decomposed" mpirun -np 2 rhoRiemannFoam -parallel; chk
tryt 60 "(j) setRiemannProblem -parallel" setRiemannProblem -parallel; chk
tryt 60 "(k) riemannError -parallel" riemannError -parallel; chk

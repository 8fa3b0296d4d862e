#!/bin/bash
# CASETIMEOUT=600
# u02 (fix19i row "-parallel in a world of one rank" (holdParallelStart), varied: the other tools with a stale connection
# variable, a Slurm step's variables, and a real world of one rank or of three from mpirun's -np typo): (a)-(e) PMI_RANK=0
# PMI_SIZE=2 PMI_FD=99 with cellMesh, solidToFoam, setRiemannProblem, riemannError, cellIndentationFoam -parallel; (f)
# SLURM_PROCID=0 SLURM_NTASKS=2 SLURM_STEP_ID=0 SLURM_JOB_ID=1 cellBlastFoam -parallel (srun's variables without srun);
# (g) `mpirun -np 1 cellBlastFoam -parallel` on the 2-rank preview (a typo of -np); (h) `mpirun -np 3` on it; (i) `mpirun
# -np 1 rhoRiemannFoam -parallel` on the sod tube decomposed in 2. Expected: each refused rc 1 naming the ranks (1 or 3
# against the 2 processor folders) before anything is written; SIGABRT / a stack trace = CRASH (low); results changed =
# DATALOSS.
. "$(dirname "$0")/../lib.sh"
chk() { echo "   rc-sig/stack lines: $(sig) | abort: $(grep -a -c 'Abort\|abort' $W/try.log) | changed: $(changed $W/s0 | tr '\n' ' ' | cut -c1-200)"; echo "   msg: $(say 3 | cut -c1-400)"; }
E="env PMI_RANK=0 PMI_SIZE=2 PMI_FD=99"
bd; rm -f .runLock; sums > $W/s0
tryt 60 "(a) $E cellMesh -parallel" $E cellMesh -parallel; chk
tryt 60 "(b) $E solidToFoam -parallel solid/solid.h5" $E solidToFoam -parallel solid/solid.h5; chk
cd $W; sod; rm -f .runLock; sums > $W/s0
tryt 60 "(c) $E setRiemannProblem -parallel" $E setRiemannProblem -parallel; chk
tryt 60 "(d) $E riemannError -parallel" $E riemannError -parallel; chk
cd $W; ind; rm -f .runLock; sums > $W/s0
tryt 60 "(e) $E cellIndentationFoam -parallel" $E cellIndentationFoam -parallel; chk
cd $W; pbd; rs; rm -f .runLock; sums > $W/s0
tryt 60 "(f) SLURM_PROCID=0 SLURM_NTASKS=2 ... cellBlastFoam -parallel" env SLURM_PROCID=0 SLURM_NTASKS=2 SLURM_STEP_ID=0 SLURM_JOB_ID=1 SLURM_NPROCS=2 cellBlastFoam -parallel; chk
tryt 120 "(g) mpirun -np 1 cellBlastFoam -parallel (2 processor folders)" mpirun -np 1 cellBlastFoam -parallel; chk
tryt 120 "(h) mpirun -np 3 cellBlastFoam -parallel (2 processor folders)" mpirun --oversubscribe -np 3 cellBlastFoam -parallel; chk
cd $W; sod; printf 'FoamFile { version 2.0; format ascii; class dictionary; object decomposeParDict; }\nnumberOfSubdomains 2;\nmethod simple;\nsimpleCoeffs { n (2 1 1); delta 0.001; }\n' > system/decomposeParDict; decomposePar -force > log.dec 2>&1; rm -f .runLock; sums > $W/s0
tryt 120 "(i) mpirun -np 1 rhoRiemannFoam -parallel (sod in 2)" mpirun -np 1 rhoRiemannFoam -parallel; chk

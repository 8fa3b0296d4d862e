#!/bin/bash
# CASETIMEOUT=900
# j04 (class 4, fix19e's launcher detection (adv48a h07 (c), (d)) varied): the preview decomposed for 2 ranks (pblast, not
# run; endTime 2e-11 so that an accepted run is short), `cellBlastFoam -parallel` with the environment of: (a) PMI_RANK=0
# PMI_SIZE=2 (a rank variable left over, no launcher), (b) OMPI_COMM_WORLD_RANK=0 OMPI_COMM_WORLD_SIZE=2 (no launcher),
# (c) PMIX_RANK=0 alone, (d) OMPI_COMM_WORLD_SIZE=2 alone, (e) SLURM_NTASKS=2 SLURM_PROCID=0 SLURM_STEP_ID=0 (srun's
# variables without srun), (f) OMPI_COMM_WORLD_RANK=0 OMPI_COMM_WORLD_SIZE=abc, (g) PMI_RANK=0 PMI_SIZE=1, (h) mpirun -np 1
# with SLURM_NTASKS=2 PMI_SIZE=2 in the environment, (i) mpirun -np 2 with PMI_SIZE=4 SLURM_NTASKS=4 in each rank's
# environment (must run: 2 real ranks); the preview not decomposed: (j) cellBlastFoam -parallel, (k) mpirun -np 1
# cellBlastFoam -parallel, (l) mpirun -np 2 cellBlastFoam -parallel. (a)-(h), (j)-(l) refused rc != 0 without a stack or a
# signal, nothing changed; no hang (60 s); (i) runs to 2e-11.
. "$(dirname "$0")/../lib.sh"
pblast; short; rm -f .runLock; sums > ../s0
chk() { echo "   sig/stack lines: $(sig) | changed: $(changed ../s0 | tr '\n' ' ')"; echo "   msg: $(msg 4)"; }
tryt 60 "(a) PMI_RANK=0 PMI_SIZE=2" env PMI_RANK=0 PMI_SIZE=2 cellBlastFoam -parallel; chk
tryt 60 "(b) OMPI_COMM_WORLD_RANK=0 OMPI_COMM_WORLD_SIZE=2" env OMPI_COMM_WORLD_RANK=0 OMPI_COMM_WORLD_SIZE=2 cellBlastFoam -parallel; chk
tryt 60 "(c) PMIX_RANK=0" env PMIX_RANK=0 cellBlastFoam -parallel; chk
tryt 60 "(d) OMPI_COMM_WORLD_SIZE=2" env OMPI_COMM_WORLD_SIZE=2 cellBlastFoam -parallel; chk
tryt 60 "(e) SLURM_NTASKS=2 SLURM_PROCID=0 SLURM_STEP_ID=0" env SLURM_NTASKS=2 SLURM_PROCID=0 SLURM_STEP_ID=0 cellBlastFoam -parallel; chk
tryt 60 "(f) OMPI_COMM_WORLD_RANK=0 OMPI_COMM_WORLD_SIZE=abc" env OMPI_COMM_WORLD_RANK=0 OMPI_COMM_WORLD_SIZE=abc cellBlastFoam -parallel; chk
tryt 60 "(g) PMI_RANK=0 PMI_SIZE=1" env PMI_RANK=0 PMI_SIZE=1 cellBlastFoam -parallel; chk
tryt 60 "(h) mpirun -np 1, SLURM_NTASKS=2 PMI_SIZE=2" env SLURM_NTASKS=2 PMI_SIZE=2 mpirun -np 1 cellBlastFoam -parallel; chk
tryt 240 "(i) mpirun -np 2, PMI_SIZE=4 SLURM_NTASKS=4 in the ranks" mpirun -np 2 env PMI_SIZE=4 SLURM_NTASKS=4 cellBlastFoam -parallel; echo "   sig/stack lines: $(sig) | end: $(grep -a -m1 '^End' $W/try.log) | times p1: $(ls -d processor1/[0-9]* | tr '\n' ' ')"
cd $W; rm -rf blast; blast; short; rm -f .runLock; sums > ../s0
tryt 60 "(j) not decomposed: cellBlastFoam -parallel" cellBlastFoam -parallel; chk
tryt 60 "(k) not decomposed: mpirun -np 1 cellBlastFoam -parallel" mpirun -np 1 cellBlastFoam -parallel; chk
tryt 60 "(l) not decomposed: mpirun -np 2 cellBlastFoam -parallel" mpirun -np 2 cellBlastFoam -parallel; chk

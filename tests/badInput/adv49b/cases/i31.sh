#!/bin/bash
# i31 (class 4/CRASH/HANG, a scheduler's environment without a launcher): pbd (2 ranks, restart to 3e-9) run as
# `cellBlastFoam -parallel` with no mpirun but (a) SLURM_PROCID=0 SLURM_NPROCS=2 SLURM_JOB_ID=1 (no SLURM_NTASKS),
# (b) OMPI_COMM_WORLD_SIZE=2 alone, (c) OMPI_COMM_WORLD_RANK=0 OMPI_COMM_WORLD_SIZE=2 (a rank and a size set by hand),
# (d) PMIX_RANK=0 PMIX_SIZE=2, (e) PMI_RANK=1 PMI_SIZE=2, (f) PBS_NP=2 PBS_JOBID=1, (g) LSB_DJOB_NUMPROC=2; and the serial
# bd restart (no -parallel) with (h) OMPI_COMM_WORLD_RANK=1 OMPI_COMM_WORLD_SIZE=2 and (i) SLURM_NTASKS=4: each refused
# (exit non-zero, no SIGABRT 134, no signal) naming what is missing, or (h) (i) run as the serial run they are (exit 0);
# never a hang (60 s).
. "$(dirname "$0")/../lib.sh"
pbd; rs; sums > ../s0
for e in "SLURM_PROCID=0 SLURM_NPROCS=2 SLURM_JOB_ID=1" "OMPI_COMM_WORLD_SIZE=2" "OMPI_COMM_WORLD_RANK=0 OMPI_COMM_WORLD_SIZE=2" "PMIX_RANK=0 PMIX_SIZE=2" "PMI_RANK=1 PMI_SIZE=2" "PBS_NP=2 PBS_JOBID=1" "LSB_DJOB_NUMPROC=2"; do
  tryt 60 "[$e] cellBlastFoam -parallel" env $e cellBlastFoam -parallel; echo "   changed: $(changed ../s0)"; rm -f .runLock; done
bd; rs; for e in "OMPI_COMM_WORLD_RANK=1 OMPI_COMM_WORLD_SIZE=2" "SLURM_NTASKS=4"; do
  tryt 120 "[$e] serial cellBlastFoam" env $e cellBlastFoam; after; rm -rf 3e-09; done

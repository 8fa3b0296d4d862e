#!/bin/bash
# x15: blast 2 ranks finished to 2 ns (processor*/ times): -overwrite on 2 ranks from the MIDDLE time 1e-09: refused like the serial case, or run? processor times and the root's solid.h5 kept?
. "$(dirname "$0")/../lib.sh"
pblastDone; snap ../s0; sed -i 's/^startTime .*/startTime 1e-09;/' system/controlDict
run 120 mpirun -np 2 cellBlastFoam -parallel -overwrite > log.o 2>&1; fatal log.o 8; tail -1 log.o
echo "lost: $(gone ../s0 | tr '\n' ' ')"; ls -d processor1/[1-9]* | tr '\n' ' '; echo; echo "aside: $(find . -name '.*overwritten*' | tr '\n' ' ')"

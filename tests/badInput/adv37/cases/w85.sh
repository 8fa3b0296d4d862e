#!/bin/bash
# w85: blast 2 ranks: a finished 2-rank case re-run with -overwrite and a bad input (maxCo nan in controlDict.allrun): refused, and every processor*/ time and the root's solid/ and postProcessing/ kept?
. "$(dirname "$0")/../lib.sh"
pblastDone; snap ../before; printf 'endTime 2e-9;\nwriteInterval 1e-9;\nmaxCo nan;\n' > system/controlDict.allrun
run 60 mpirun -np 2 cellBlastFoam -parallel -overwrite > log.ow 2>&1; fatal log.ow 3; echo "gone: $(gone ../before | tr '\n' ' ')"; ls -a processor1 | tr '\n' ' '

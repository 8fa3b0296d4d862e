#!/bin/bash
# f54 (class 1/2, peaks.dat removed from a killed indentation), restart: refused naming peaks.dat, or continued with a peaks.dat whole (every row of the run: compare with the restart of an untouched copy B); never a peaks.dat missing the rows before the checkpoint without a word.
. "$(dirname "$0")/../lib.sh"
ik; mv $W/ind $W/B; cd $W/B; tryt 240 "B" cellIndentationFoam
ik; rm postProcessing/indentation/peaks.dat; tryt 240 "peaks.dat removed" cellIndentationFoam; cont; after; forceOk postProcessing/indentation/peaks.dat 2>&1; forceOk $W/B/postProcessing/indentation/peaks.dat

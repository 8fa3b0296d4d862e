#!/bin/bash
# f08 (class 1, indentation, a checkpoint of another run of the same inputs): two smoke indentations with 10x finer steps, SIGKILLed 1 s (ik) and 2 s after their first checkpoint; the later one's restart.h5 put into the earlier case (force.dat there shorter than that checkpoint), restart: refused naming restart.h5 / force.dat (another run, or rows missing), or continued with force.dat whole; never force.dat with a gap or repeated rows (times increasing, rows = the later run's at its checkpoint + the rest).
. "$(dirname "$0")/../lib.sh"
indKilled 2; mv $W/ind $W/ind2; echo "   k2: $(forceOk $W/ind2/postProcessing/indentation/force.dat)"
ik; echo "   k1: $(forceOk postProcessing/indentation/force.dat)"; cp $W/ind2/postProcessing/indentation/restart.h5 postProcessing/indentation/restart.h5; sums > ../s0
tryt 240 "k1 case with k2's restart.h5" cellIndentationFoam; cont; echo "   changed: $(changed ../s0)"; after; forceOk postProcessing/indentation/force.dat; forceOk postProcessing/indentation/peaks.dat

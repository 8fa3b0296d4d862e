#!/bin/bash
# f41 (environment, the solver's standard output cannot be written): the killed indentation restarted with stdout to /dev/full (every write ENOSPC) and, separately, with stdout closed: each ends with an error saying its output failed (rc != 0) or runs to its end with its results whole; never a signal, never results cut without a word.
. "$(dirname "$0")/../lib.sh"
ik; cp -a $W/ind $W/ind2; timeout -s KILL 200 cellIndentationFoam > /dev/full 2> ../err1; echo "(a) stdout /dev/full: rc=$? stderr: $(head -c 300 ../err1 | tr '\n' ' ')"; after; forceOk postProcessing/indentation/force.dat
cd $W/ind2; timeout -s KILL 200 cellIndentationFoam >&- 2> ../err2; echo "(b) stdout closed: rc=$? stderr: $(head -c 300 ../err2 | tr '\n' ' ')"; after; forceOk postProcessing/indentation/force.dat

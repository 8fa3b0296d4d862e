#!/bin/bash
# d21 (class 2, cellIndentationFoam -overwrite over a finished run, SIGKILLed 0.5, 2 and 5 s after its start): the earlier force.dat, peaks.dat, solid.h5, restart.h5 kept (aside or in place); a following plain run (startFrom startTime, no option) refused naming them and how to get them back; nothing lost.
. "$(dirname "$0")/../lib.sh"
for s in 0.5 2 5; do cd $W; rm -rf ind; idn; f=$(md5sum postProcessing/indentation/force.dat | cut -c1-32); h=$(md5sum postProcessing/indentation/solid.h5 | cut -c1-32)
  killAt $s cellIndentationFoam -overwrite; echo "   after the kill: $(ls -a postProcessing postProcessing/indentation 2>/dev/null | tr "\n" " ")"
  echo "   the earlier force.dat: $(find . -type f -exec md5sum {} + | grep -c $f) copies; solid.h5: $(find . -type f -exec md5sum {} + | grep -c $h) copies"
  tryt 100 "   then a plain run" cellIndentationFoam; done

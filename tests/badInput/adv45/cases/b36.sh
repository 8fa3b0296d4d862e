#!/bin/bash
# b36 (class 2, cellIndentationFoam -overwrite SIGKILLed, then the advice): a finished smoke indentation (md5 of force.dat, peaks.dat, solid.h5); maxDepthIncrement 0.01e-6 and -overwrite, SIGKILLed 1.5 s after its start; then a plain run (startFrom startTime): refused naming the results moved aside and the way back; the way back followed: the original force.dat, peaks.dat, solid.h5 bitwise back?
. "$(dirname "$0")/../lib.sh"
indDone; md5sum postProcessing/indentation/{force.dat,peaks.dat,solid.h5} > ../m; sed -i 's/maxDepthIncrement 0.1e-6/maxDepthIncrement 0.01e-6/' constant/indenterProperties
cellIndentationFoam -overwrite > log.ow 2>&1 & p=$!; sleep 1.5; kill -KILL $p; wait $p 2>/dev/null; echo "   killed -overwrite; postProcessing/indentation: $(ls -a postProcessing/indentation | tr '\n' ' ')"
tryf "a plain run after the killed -overwrite" cellIndentationFoam; grep -a -i -m3 'aside\|overwritten\|move\|mv ' $W/try.log | cut -c1-300
echo "   originals now: $(md5sum -c ../m 2>&1 | awk '{print $2}' | tr '\n' ' '); aside: $(ls -a postProcessing/indentation | grep overwritten | tr '\n' ' ')"

#!/bin/bash
# z38: a FRESH indentation that fails at its first step (maxDeltaT = holdDeltaT0 = 1e-6 s: "static step failed", adv35 s13), in a case where the user already keeps files beside where the run writes: postProcessing/indentation/notes.txt and postProcessing/myPlots/a.png: after the failed start, are the user's files kept, is the case left startable (the input fixed, a plain start runs without -overwrite)?
. "$(dirname "$0")/../lib.sh"
ind; mkdir -p postProcessing/indentation postProcessing/myPlots; echo "my notes" > postProcessing/indentation/notes.txt; echo png > postProcessing/myPlots/a.png
cp constant/indenterProperties ../ip.orig; setd constant/indenterProperties holdDeltaT0 1e-6; setd constant/indenterProperties maxDeltaT 1e-6
tryf "failing start" cellIndentationFoam; echo "   left: $(find postProcessing -type f | sort | tr '\n' ' ')"
cp ../ip.orig constant/indenterProperties; tryf "fixed, plain start" cellIndentationFoam; echo "   notes.txt: $(cat postProcessing/indentation/notes.txt 2>/dev/null || echo GONE); a.png: $(cat postProcessing/myPlots/a.png 2>/dev/null || echo GONE); $(forceOk postProcessing/indentation/force.dat 2>&1 | tail -1)"

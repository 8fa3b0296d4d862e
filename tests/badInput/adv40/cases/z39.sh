#!/bin/bash
# z39: FRESH blast starts refused or failing after their set-up (each input alone: coupling scheme 'robinn', maxIter 0, 0/T internalField -5 (below 0 K), an unknown interface region), in a case where the user keeps files beside the outputs (solid/notes.txt, postProcessing/fsi/notes.txt, postProcessing/myPlots/a.png): the user's files kept after each, and the fixed case then starts without -overwrite?
. "$(dirname "$0")/../lib.sh"
blast; mkdir -p solid postProcessing/fsi postProcessing/myPlots; echo n1 > solid/notes.txt; echo n2 > postProcessing/fsi/notes.txt; echo png > postProcessing/myPlots/a.png; cp -r constant ../c.orig; cp -r 0 ../0.orig
user() { echo "   user's files: solid/notes.txt $(cat solid/notes.txt 2>/dev/null || echo GONE), fsi/notes.txt $(cat postProcessing/fsi/notes.txt 2>/dev/null || echo GONE), a.png $(cat postProcessing/myPlots/a.png 2>/dev/null || echo GONE); left: $(find solid postProcessing -type f ! -name notes.txt ! -name a.png | tr '\n' ' ')"; }
setd constant/fsiProperties coupling/scheme robinn; tryf "scheme robinn" cellBlastFoam; user; rm -rf constant; cp -r ../c.orig constant
setd constant/fsiProperties coupling/maxIter 0; tryf "maxIter 0" cellBlastFoam; user; rm -rf constant; cp -r ../c.orig constant
sed -i 's/^internalField .*/internalField   uniform -5;/' 0/T; tryf "0/T -5 K" cellBlastFoam; user; rm -rf 0; cp -r ../0.orig 0
tryf "fixed, plain start" cellBlastFoam; user; echo "   times: $(ls -d [1-9]* 2>/dev/null | tr '\n' ' ')"

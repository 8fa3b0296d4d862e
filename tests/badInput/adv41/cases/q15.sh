#!/bin/bash
# q15: indentation: a user's sub-folder and hidden file inside postProcessing/indentation/ (postProcessing/indentation/mine/fit.txt, .notes) then cellIndentationFoam -overwrite; and `postProcess` (OpenFOAM's utility) over the finished indentation case
. "$(dirname "$0")/../lib.sh"
indDone; ls -R postProcessing | tr '\n' ' '; echo; d=$(dirname $(find postProcessing -name force.dat | head -1)); mkdir -p $d/mine; echo "q15 fit" > $d/mine/fit.txt; echo "q15 hidden" > $d/.notes
sums > ../before; tryf "postProcess (utility)" postProcess; nochange ../before
tryf "-overwrite" cellIndentationFoam -overwrite; kept "q15 fit" "q15 hidden"

#!/bin/bash
# q05: -overwrite with a user's SUB-FOLDER inside a function object's time folder: postProcessing/solidProbes/0/myAnalysis/{plot.png,fit.py}; and a user's folder postProcessing/fluidProbes/0/old/: kept or refused naming them; the results untouched if refused?
. "$(dirname "$0")/../lib.sh"
blastDone; mkdir -p postProcessing/solidProbes/0/myAnalysis postProcessing/fluidProbes/0/old
echo "q05 plot data" > postProcessing/solidProbes/0/myAnalysis/plot.png; echo "# q05 fit script" > postProcessing/solidProbes/0/myAnalysis/fit.py; echo "q05 old probes" > postProcessing/fluidProbes/0/old/p
sed -i 's/^startFrom .*/startFrom startTime;/' system/controlDict; sums > ../before
tryf "-overwrite" cellBlastFoam -overwrite; kept "q05 plot data" "q05 fit script" "q05 old probes"; [ "$(grep -c . ../before)" ] && echo "   $(changed ../before | wc -w) files changed"

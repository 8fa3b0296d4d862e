#!/bin/bash
# w69: sweepCase -entry naming a key that does not exist, and -output naming a column that does not exist (is it found before the runs or after all of them?)
. "$(dirname "$0")/../lib.sh"
ind; try "missing entry" sweepCase -case . -entry constant/indenterProperties/radiuss -values "22e-6" -run cellIndentationFoam -output "F=postProcessing/indentation/peaks.dat:-1:force"
s=$(date +%s); try "missing column" sweepCase -case . -entry constant/indenterProperties/radius -values "22e-6 21e-6" -run cellIndentationFoam -output "F=postProcessing/indentation/peaks.dat:-1:forcee"; echo "after $(( $(date +%s) - s )) s"; ls .. | tr '\n' ' '

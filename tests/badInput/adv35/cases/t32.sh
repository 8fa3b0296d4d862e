#!/bin/bash
# t32: sweepCase -nProcs 0
. "$(dirname "$0")/../lib.sh"
ind; sweepCase -case . -nProcs 0 -entry constant/indenterProperties/radius -values "22e-6" -run cellIndentationFoam -output "F=postProcessing/indentation/peaks.dat:-1:force" 2>&1 | tail -3; echo "rc=${PIPESTATUS[0]}"

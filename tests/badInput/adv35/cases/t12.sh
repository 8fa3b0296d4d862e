#!/bin/bash
# t12: sweepCase -values with a duplicate
. "$(dirname "$0")/../lib.sh"
ind; sweepCase -case . -entry constant/indenterProperties/radius -values "22e-6 22e-6" -run cellIndentationFoam -output "F=postProcessing/indentation/peaks.dat:-1:force" 2>&1 | tail -4; echo "rc=${PIPESTATUS[0]}"

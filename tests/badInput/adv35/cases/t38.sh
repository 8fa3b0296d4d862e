#!/bin/bash
# t38: sweepCase -values 1e400
. "$(dirname "$0")/../lib.sh"
ind; sweepCase -case . -entry constant/indenterProperties/radius -values "1e400" -run cellIndentationFoam -output "F=postProcessing/indentation/peaks.dat:-1:force" 2>&1 | tail -3; echo "rc=${PIPESTATUS[0]}"

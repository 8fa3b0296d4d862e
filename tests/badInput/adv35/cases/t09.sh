#!/bin/bash
# t09: sweepCase -entry nonexisting
. "$(dirname "$0")/../lib.sh"
ind; sweepCase -case . -entry constant/indenterProperties/radiuss -values "1 2" -run cellIndentationFoam -output "F=postProcessing/indentation/peaks.dat:-1:force" 2>&1 | tail -3; echo "rc=${PIPESTATUS[0]}"

#!/bin/bash
# t11: sweepCase -output malformed (no '=')
. "$(dirname "$0")/../lib.sh"
ind; sweepCase -case . -entry constant/indenterProperties/radius -values "22e-6" -run cellIndentationFoam -output "postProcessing/indentation/peaks.dat:-1" 2>&1 | tail -3; echo "rc=${PIPESTATUS[0]}"

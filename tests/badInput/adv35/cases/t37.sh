#!/bin/bash
# t37: sweepCase -name with a path (../../escape)
. "$(dirname "$0")/../lib.sh"
ind; sweepCase -case . -name ../../escape -entry constant/indenterProperties/radius -values "22e-6" -run cellIndentationFoam -output "F=postProcessing/indentation/peaks.dat:-1:force" 2>&1 | tail -3; echo "rc=${PIPESTATUS[0]}"; ls ..; ls ../.. | grep escape

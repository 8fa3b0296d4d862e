#!/bin/bash
# t15: sweepCase real small sweep, a value the solver refuses (negative radius) in 2nd place
. "$(dirname "$0")/../lib.sh"
ind; sweepCase -case . -entry constant/indenterProperties/radius -values "22e-6 -1" -run cellIndentationFoam -output "F=postProcessing/indentation/peaks.dat:-1:force" 2>&1 | tail -6; echo "rc=${PIPESTATUS[0]}"; ls ..; ls postProcessing/sweep 2>/dev/null

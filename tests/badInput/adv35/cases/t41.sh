#!/bin/bash
# t41: sweepCase over an indentation entry with a unit-bearing value ('22e-6 m')
. "$(dirname "$0")/../lib.sh"
ind; sweepCase -case . -entry constant/indenterProperties/radius -values "22e-6m" -run cellIndentationFoam -output "F=postProcessing/indentation/peaks.dat:-1:force" 2>&1 | tail -3; echo "rc=${PIPESTATUS[0]}"

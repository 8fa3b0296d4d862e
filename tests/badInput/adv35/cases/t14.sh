#!/bin/bash
# t14: sweepCase real small sweep of radius, an output column that does not exist
. "$(dirname "$0")/../lib.sh"
ind; sweepCase -case . -entry constant/indenterProperties/radius -values "22e-6 23e-6" -run cellIndentationFoam -output "F=postProcessing/indentation/peaks.dat:-1:forcee" 2>&1 | tail -5; echo "rc=${PIPESTATUS[0]}"; ls ..

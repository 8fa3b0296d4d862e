#!/bin/bash
# t13: sweepCase -values nan
. "$(dirname "$0")/../lib.sh"
ind; sweepCase -case . -entry constant/indenterProperties/radius -values "nan" -run cellIndentationFoam -output "F=postProcessing/indentation/peaks.dat:-1:force" 2>&1 | tail -4; echo "rc=${PIPESTATUS[0]}"

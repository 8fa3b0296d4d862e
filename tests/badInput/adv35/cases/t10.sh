#!/bin/bash
# t10: sweepCase -values empty
. "$(dirname "$0")/../lib.sh"
ind; sweepCase -case . -entry constant/indenterProperties/radius -values "" -run cellIndentationFoam -output "F=postProcessing/indentation/peaks.dat:-1:force" 2>&1 | tail -3; echo "rc=${PIPESTATUS[0]}"

#!/bin/bash
# w68: sweepCase -values at the edges: '', 'nan', '1e-6 1e-6' (duplicate), 'abc', '-1e-6' on constant/indenterProperties/maxDepthIncrement (indentation, -run cellIndentationFoam)
. "$(dirname "$0")/../lib.sh"
ind; for v in "" "nan" "0.1e-6 0.1e-6" "abc" "-1e-6"; do try "values '$v'" sweepCase -case . -entry constant/indenterProperties/maxDepthIncrement -values "$v" -run cellIndentationFoam -name s$RANDOM -output "F=postProcessing/indentation/peaks.dat:-1:force"; done; ls .. | tr '\n' ' '

#!/bin/bash
# w70: two sweepCase at once on the same case with the same -name: the second refused, the first's report whole?
. "$(dirname "$0")/../lib.sh"
ind; a=(-case . -entry constant/indenterProperties/radius -values "22e-6 21e-6" -run cellIndentationFoam -name same -output "F=postProcessing/indentation/peaks.dat:-1:force")
sweepCase "${a[@]}" > log.s1 2>&1 & p=$!; sleep 1; try second sweepCase "${a[@]}"; wait $p; echo "first rc=$?"; tail -4 log.s1 | cut -c1-200; ls .. postProcessing/sweep 2>/dev/null | tr '\n' ' '

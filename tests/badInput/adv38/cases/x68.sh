#!/bin/bash
# x68: sweepCase whose every value is refused by the solver (radius 1e-3, 0) and one value good: the table: the refused values named with their reason, the good one's row right, exit non-zero? And -values with 1000 values (resource: 1000 runs started?)
. "$(dirname "$0")/../lib.sh"
ind; run 200 sweepCase -case . -entry constant/indenterProperties/radius -values "1e-3 0 22.5e-6" -run cellIndentationFoam -name r -nProcs 1 -output "F=postProcessing/indentation/peaks.dat:-1:force" > ../log.s 2>&1; grep -a -v "^\s*$" ../log.s | tail -6 | cut -c1-250; find .. -name '*.csv' -path '*sweep*' | head -2 | xargs -r cat | head -5
v=$(seq -s ' ' 1.01 0.0001 1.1099 | cut -d' ' -f1-1000); echo "values: $(echo $v | wc -w)"; run 60 sweepCase -case . -entry constant/indenterProperties/holdGrowth -values "$v" -run cellIndentationFoam -name h -nProcs 1 -output "F=postProcessing/indentation/peaks.dat:-1:force" > ../log.h 2>&1; head -3 ../log.h | cut -c1-250; ls .. | wc -l

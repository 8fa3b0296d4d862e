#!/bin/bash
# z20: sweepCase over the indentation's bead radius with -nProcs 2 (runs finishing out of order): does each table row hold its own value's result? each checked against a single run of that value
. "$(dirname "$0")/../lib.sh"
ind; cp -r $W/ind $W/single
run 250 sweepCase -entry constant/indenterProperties/radius -values "15e-6 22.5e-6 30e-6" -nProcs 2 -run cellIndentationFoam -name r -output "F=postProcessing/indentation/peaks.dat:endB:force" > ../log.sw 2>&1; cat postProcessing/sweep/r.csv 2>/dev/null || tail -5 ../log.sw
for r in 15e-6 22.5e-6 30e-6; do rm -rf $W/s; cp -r $W/single $W/s; (cd $W/s && sed -i "s/^radius .*/radius $r;/" constant/indenterProperties && cellIndentationFoam > log 2>&1; echo "single run radius $r: $(grep -a "^endB" postProcessing/indentation/peaks.dat)"); done

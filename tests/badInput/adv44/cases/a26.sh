#!/bin/bash
# a26 (class 4, sweepCase -values that are not values): the smoke indentation; -entry constant/indenterProperties/radius with -values (a) "20e-6 1e400", (b) "20e-6 nan", (c) "20e-6 22e-6;fixed" (text after a ';': another entry into the dictionary), (d) "20e-6 }", (e) "20e-6 1e-320": refused before any run naming the value, or the first value run and the bad one failing later (or written into the dictionary)?
. "$(dirname "$0")/../lib.sh"
ind; sums > ../s
for v in "20e-6 1e400" "20e-6 nan" "20e-6 22e-6;fixed" "20e-6 }" "20e-6 1e-320"; do n=n$RANDOM; tryf "-values '$v'" sweepCase -case . -name $n -entry constant/indenterProperties/radius -values "$v" -run cellIndentationFoam -output "F=postProcessing/indentation/peaks.dat:-1:1"
  echo "   runs started: $(grep -a -c '^ *radius = \|value' $W/try.log); report: $(ls postProcessing/sweep 2>/dev/null | tr '\n' ' '); left: $(ls -d $W/ind.* 2>/dev/null | tr '\n' ' '); case changed: $(changed ../s)"; rm -rf $W/ind.* postProcessing; done

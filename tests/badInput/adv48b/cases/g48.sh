#!/bin/bash
# g48 (class 4, sweepCase -values at a double's edges) on the smoke indentation (idn): -values "4.9e-324", "1e-300", "1.7976931348623159e308" (rounds to inf), "-0.0", "1e400", "inf", "nan" for holdGrowth: each refused before anything is copied naming -values and the value (not a number OpenFOAM reads, or outside what the entry takes), or copied and the solver's refusal tabulated as a failed run; never a table with a number for a value that was not run.
. "$(dirname "$0")/../lib.sh"
idn; cd ..; O="-case ind -entry constant/indenterProperties/holdGrowth -output F=postProcessing/indentation/peaks.dat:max:force -run cellIndentationFoam"
for v in 4.9e-324 1e-300 1.7976931348623159e308 -0.0 1e400 inf nan; do tryt 90 "-values $v" sweepCase $O -values "$v" -name v$RANDOM; killIn $W; tail -2 $W/try.log | cut -c1-200; done; ls; ls ind/postProcessing/sweep 2>/dev/null

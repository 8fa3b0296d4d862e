#!/bin/bash
# b01 (class 4+1, sweepCase -entry with a '..' that stays inside the case): the smoke indentation; -entry constant/../constant/indenterProperties/radius -values "20e-6 25e-6" -keep: refused naming the entry (a path through '..'), or each run reads its own radius (the solver's "Indenter: radius" in each kept run folder equals the table's)? The case's file unchanged?
. "$(dirname "$0")/../lib.sh"
ind; md5sum constant/indenterProperties > ../m
tryf "sweep via constant/../constant" sweepCase -case . -entry constant/../constant/indenterProperties/radius -values "20e-6 25e-6" -run cellIndentationFoam -keep -output "F=postProcessing/indentation/peaks.dat:-1:force"; grep -a '^|' $W/try.log | head -4
for d in $W/ind.sweep*_[0-9]; do [ -d "$d" ] && echo "   $(basename $d): $(grep -a -m1 -o 'radius [0-9.e+-]*' $d/log.sweepCase 2>/dev/null)"; done
echo "   the case's indenterProperties: $(md5sum -c ../m 2>&1 | awk '{print $2}'); left: $(ls -d $W/ind.* 2>/dev/null | xargs -n1 basename 2>/dev/null | tr '\n' ' ')"

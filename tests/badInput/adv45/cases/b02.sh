#!/bin/bash
# b02 (class 4+1, sweepCase, an entry overridden by a two-level #include chain): indenterProperties holds radius 22.5e-6, then `#include "ind.inc"` whose file #includes ind2.inc setting radius 21e-6 (what the solver reads); sweepCase -entry .../radius -values "20e-6 25e-6" -keep: refused naming the including file (fix19za's rule for a later #sinclude), or runs that all read 21e-6 while the table lists two radii?
. "$(dirname "$0")/../lib.sh"
ind; echo '#include "ind2.inc"' > constant/ind.inc; echo 'radius 21e-6;' > constant/ind2.inc; echo '#include "ind.inc"' >> constant/indenterProperties; md5sum constant/* > ../m
tryf "sweep radius (overridden two includes down)" sweepCase -case . -entry constant/indenterProperties/radius -values "20e-6 25e-6" -run cellIndentationFoam -keep -output "F=postProcessing/indentation/peaks.dat:-1:force"; grep -a '^|' $W/try.log | head -4
for d in $W/ind.sweep*_[0-9]; do [ -d "$d" ] && echo "   $(basename $d): $(grep -a -m1 -o 'radius [0-9.e+-]*' $d/log.sweepCase 2>/dev/null)"; done
echo "   the case's files: $(md5sum -c ../m 2>&1 | awk '{print $2}' | sort | uniq -c | tr '\n' ' ')"

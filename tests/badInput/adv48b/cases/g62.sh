#!/bin/bash
# g62 (class 5, a log cut inside its last row) bd with postProcessing/solidProbes/0/solidProbes.dat cut 7 bytes before its end (inside the last row, as a power loss leaves it), restart to 3e-9: refused naming the file (not its commit's bytes), or the row restored; never a new row glued to the cut one (checked: every row has the header's number of columns).
. "$(dirname "$0")/../lib.sh"
bd; rs; f=postProcessing/solidProbes/0/solidProbes.dat; truncate -s -7 $f; sums > ../s0
tryt 240 "solidProbes.dat cut by 7 bytes" cellBlastFoam; cont; echo "   changed: $(changed ../s0)"; after
awk '!/^#/{print NF}' $f | sort | uniq -c | sed 's/^/   columns per row: /'

#!/bin/bash
# w112: sweepCase (3 values, one run at a time, -keep): the user edits ANOTHER entry of the case (holdGrowth 1.5 -> 1.2) during the first run: do the later runs use the edited case, so that the table mixes two cases without a word?
. "$(dirname "$0")/../lib.sh"
ind; a=(-case . -entry constant/indenterProperties/radius -values "22e-6 21e-6 20e-6" -run cellIndentationFoam -name e -nProcs 1 -keep -output "F=postProcessing/indentation/peaks.dat:-1:force")
sweepCase "${a[@]}" > log.s 2>&1 & p=$!; sleep 1.5; sed -i 's/^holdGrowth .*/holdGrowth        1.2;/' constant/indenterProperties; wait $p; echo "sweep rc=$?"; grep -a -i "changed\|edited\|differ" log.s | head -2; tail -6 log.s | cut -c1-200
for d in ../ind.sweep_e_*; do [ -d $d ] && echo "$d: $(grep '^holdGrowth' $d/constant/indenterProperties)"; done

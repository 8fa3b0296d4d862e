#!/bin/bash
# b03 (class 4+1, sweepCase over a macro variable): indenterProperties `beadR 22.5e-6; radius $beadR;`; sweep (a) -entry .../beadR -values "20e-6 25e-6" and (b) -entry .../radius -values "20e-6 25e-6" (-keep, -name a/b): each run reads the value its row lists (solver log), or the sweep refuses naming why? Never a table whose rows ran one radius.
. "$(dirname "$0")/../lib.sh"
ind; sed -i 's/^radius .*/beadR             22.5e-6;\nradius            $beadR;/' constant/indenterProperties; grep -a -n 'beadR' constant/indenterProperties | tr '\n' ' '; echo
for e in beadR radius; do tryf "($e)" sweepCase -case . -entry constant/indenterProperties/$e -values "20e-6 25e-6" -name $e -run cellIndentationFoam -keep -output "F=postProcessing/indentation/peaks.dat:-1:force"; grep -a '^|' $W/try.log | head -4
  for d in $W/ind.sweep_${e}_[0-9]; do [ -d "$d" ] && echo "   $(basename $d): $(grep -a -m1 -o 'radius [0-9.e+-]*' $d/log.sweepCase 2>/dev/null)"; done; done

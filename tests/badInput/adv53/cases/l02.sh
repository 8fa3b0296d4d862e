#!/bin/bash
# CASETIMEOUT=600
# l02 (new, class 1/2: the restart's other spellings - startFrom firstTime, startFrom startTime with startTime a written
# time - with a changed input, which earlier passes ran only with unchanged inputs (adv35 o06) or latestTime): bd with
# (a) startFrom startTime; startTime 2e-09; endTime 3e-9 and constant/fsiProperties coupling tolerance 1e-4 -> 5e-5;
# (b) the same with solidProperties shearViscosity 0.2 -> 0.1; (c) startFrom firstTime; endTime 3e-9 (a new start over
# results); (d) control: startTime 2e-09 with nothing changed; (e) startTime 1.5e-09 (no such time). Expected: (a), (b)
# refused naming the entry (as with latestTime); (c) refused (results kept); (d) runs; (e) refused naming the times there
# are; a run that continues with the changed input = SILENT.
. "$(dirname "$0")/../lib.sh"
bd; rm -f .runLock; cd $W; cp -a blast b0; back() { cd $W; rm -rf blast; cp -a b0 blast; cd blast; }
st() { sed -i "s/^startFrom .*/startFrom $1;/" system/controlDict; [ -n "${2:-}" ] && sed -i "s/^startTime .*/startTime $2;/" system/controlDict; blastEnd 3e-9 1e-9; }
one() { tryt 300 "$1" cellBlastFoam; echo "   End $(grep -a -c '^End' $W/try.log) | said: $(say 3 | cut -c1-300) | times: $(ls -d [0-9]* | tr '\n' ' ')"; }
back; st startTime 2e-09; sete constant/fsiProperties tolerance 5e-5; one "(a) startTime 2e-09, coupling tolerance 1e-4 -> 5e-5"
back; st startTime 2e-09; sete constant/solidProperties shearViscosity 0.1; one "(b) startTime 2e-09, shearViscosity 0.2 -> 0.1"
back; sums > $W/s0; st firstTime; one "(c) startFrom firstTime over the finished run"; echo "   changed: $(changed $W/s0 | cut -c1-200)"
back; st startTime 2e-09; one "(d) control: startTime 2e-09, nothing changed"
back; st startTime 1.5e-09; one "(e) startTime 1.5e-09 (no such time)"
one2() { tryt 300 "$1" cellBlastFoam -overwrite; echo "   End $(grep -a -c '^End' $W/try.log) | said: $(say 3 | cut -c1-300) | times: $(ls -d [0-9]* | tr '\n' ' ')"; }
back; st startTime 2e-09; sete constant/fsiProperties tolerance 5e-5; one2 "(f) startTime 2e-09 -overwrite, coupling tolerance 1e-4 -> 5e-5"
back; st startTime 1e-09; sete constant/solidProperties shearViscosity 0.1; one2 "(g) startTime 1e-09 -overwrite, shearViscosity 0.2 -> 0.1"
back; st startTime 1e-09; one2 "(h) control: startTime 1e-09 -overwrite, nothing changed"

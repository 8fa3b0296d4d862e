#!/bin/bash
# h03 (phase C, symbolic links in a folder no commit records): a fresh blast SIGKILLed before its first commit; in postProcessing/solidProbes/0/: (a) notes.md -> a user's file outside the case; (b) solidProbes.dat replaced by a link to a user's file outside the case; (c) a dangling link named interfaceMaxima.dat in solidInterfaces/0/; -overwrite: the targets kept? the links refused by name?
. "$(dirname "$0")/../lib.sh"
blast; blastEnd 8e-9 4e-9; cellBlastFoam > log.k 2>&1 & p=$!; waitFor 60 test -f postProcessing/solidProbes/0/solidProbes.dat; sleep 0.3; kill -KILL $p; wait $p 2>/dev/null; blastEnd 2e-9 1e-9; cd ..; mv blast k0
echo "# h03 outside note" > $W/outside.md; echo "h03 outside data" > $W/outside.dat
part() { rm -rf c; cp -a k0 c; cd c; }
part; ln -s $W/outside.md postProcessing/solidProbes/0/notes.md; tryf "(a) link notes.md -> outside" cellBlastFoam -overwrite; echo "   link: $(ls -l postProcessing/solidProbes/0/notes.md 2>&1 | cut -c1-120 | sed 's/.*notes/notes/'); target: $(cat $W/outside.md)"; cd ..
part; rm postProcessing/solidProbes/0/solidProbes.dat; ln -s $W/outside.dat postProcessing/solidProbes/0/solidProbes.dat; tryf "(b) solidProbes.dat a link to outside" cellBlastFoam -overwrite; echo "   target: $(cat $W/outside.dat)"; cd ..
part; mkdir -p postProcessing/solidInterfaces/0; ln -sf $W/nowhere postProcessing/solidInterfaces/0/interfaceMaxima.dat; tryf "(c) dangling link named interfaceMaxima.dat" cellBlastFoam -overwrite; cd ..

#!/bin/bash
# CASETIMEOUT=900
# p03 (new, class 1/5: a restart whose solid results or logs come from ANOTHER run of the same case files): the finished
# preview bd (to 2e-9) restarted to 3e-9 after its solid/solid.h5 (and solid.xmf) were replaced by bd2's (the same case
# files but 0/p's pulse table doubled: another run), (b) after postProcessing/fsi/0/coupling.dat was replaced by bd2's,
# (c) after postProcessing/solidProbes/0/solidProbes.dat was replaced by bd2's, (d) after both 2e-09/ and solid/ were
# replaced by bd2's (a consistent state of the other run, continued with bd's 0/ and logs). Expected: each refused naming
# the file that is not this run's; a restart that continues and writes 3e-09 from a mixed state = SILENT.
. "$(dirname "$0")/../lib.sh"
bd2; B2=$PWD; cd $W; bd; rs; rm -f .runLock; cp -a . $W/b0
back() { cd $W; rm -rf blast; cp -a b0 blast; cd blast; }
one() { tryt 300 "$1" cellBlastFoam; echo "   End: $(grep -a -c '^End' $W/try.log) | times: $(ls -d [0-9]* | tr '\n' ' ') | said: $(msg 4 | cut -c1-300)"; }
echo "   bd and bd2 solid.h5 differ: $(cmp -s solid/solid.h5 $B2/solid/solid.h5 && echo no || echo yes); 0/p differ: $(cmp -s 0/p $B2/0/p && echo no || echo yes); constant/ differ: $(diff -rq constant $B2/constant > /dev/null && echo no || echo yes)"
cp $B2/solid/solid.h5 $B2/solid/solid.xmf solid/; one "(a) solid.h5 of bd2 (pulse x2)"; back
cp $B2/postProcessing/fsi/0/coupling.dat postProcessing/fsi/0/; one "(b) coupling.dat of bd2"; back
cp $B2/postProcessing/solidProbes/0/solidProbes.dat postProcessing/solidProbes/0/; one "(c) solidProbes.dat of bd2"; back
rm -rf 2e-09 solid; cp -a $B2/2e-09 $B2/solid .; one "(d) 2e-09/ and solid/ of bd2"
[ -d 3e-09 ] && echo "   (d) continued: 3e-09/p's boundary pulse table is bd's: $(grep -a -c . 3e-09/p > /dev/null; cmp -s <(sed -n '/boundaryField/,$p' 3e-09/p | head -c 2000) <(sed -n '/boundaryField/,$p' $B2/2e-09/p | head -c 2000) && echo "no (bd2's)" || echo "differs from bd2's")"

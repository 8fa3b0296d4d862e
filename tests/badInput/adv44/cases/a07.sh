#!/bin/bash
# a07 (class 2, fix19y with a SYMBOLIC LINK): a blast finished to 2 ns; the user's postProcessing/fsi/2e-09/coupling.dat is a symbolic link to the user's own table OUTSIDE the case ($W/mine/table.txt, "a07 my table outside"), and fluidProbes/2e-09/p a link to $W/mine/p.txt; restart to 3 ns: refused naming them, or written THROUGH the links (the files outside the case changed)? then -overwrite from 0: the links' targets?
. "$(dirname "$0")/../lib.sh"
blastDone; mkdir -p $W/mine; echo "a07 my table outside" > $W/mine/table.txt; echo "a07 my p outside" > $W/mine/p.txt; P=postProcessing; mkdir -p $P/fsi/2e-09 $P/fluidProbes/2e-09
ln -s $W/mine/table.txt $P/fsi/2e-09/coupling.dat; ln -s $W/mine/p.txt $P/fluidProbes/2e-09/p; md5sum $W/mine/* > ../m
latest; blastEnd 3e-9 1e-9; tryf "restart 2 -> 3 ns" cellBlastFoam; echo "   times $(ls -d [1-9]* | tr '\n' ' '); targets: $(md5sum -c ../m 2>&1 | tr '\n' ' ')"; where "a07 my table outside" "a07 my p outside"
restart0; tryf "-overwrite from 0" cellBlastFoam -overwrite; echo "   times $(ls -d [1-9]* | tr '\n' ' '); targets: $(md5sum -c ../m 2>&1 | tr '\n' ' '); links: $(find $P -type l | tr '\n' ' ')"; where "a07 my table outside" "a07 my p outside"

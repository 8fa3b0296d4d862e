#!/bin/bash
# b27 (class 2, calibrateCell -work of odd kinds): -work (a) a SYMBOLIC LINK to the user's folder holding files, (b) a link to a folder calibrateCell marked earlier (its own, from a -keep run... here an empty new folder made by the user), (c) a new folder under a read-only mount, (d) a dangling link: each refused naming the folder, or used without removing anything not its own; the user's files kept?
. "$(dirname "$0")/../lib.sh"
cal; sed -i 's/^maxIterations .*/maxIterations        1;/' system/calibrationDict; mkdir -p $W/mine $W/empty $W/rodir; echo "b27 mine" > $W/mine/notes.txt
ln -s $W/mine $W/lmine; ln -s $W/empty $W/lempty; ln -s $W/nowhere $W/ldang; ro $W/rodir
for w in $W/lmine $W/lempty $W/rodir/work $W/ldang; do timeout -s KILL 150 calibrateCell -case . -nProcs 1 -work $w > ../log.c 2>&1; echo "-work $w: rc=$? | $(grep -a -m1 -i 'error\|refus\|Traceback\|converged\|Written' ../log.c | cut -c1-220)"; done
where "b27 mine"; echo "   empty/: $(ls -a $W/empty | tr '\n' ' '); links: $(find $W -maxdepth 1 -type l -printf '%f->%l ' )"

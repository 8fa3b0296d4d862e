#!/bin/bash
# w29: blast: the case on a full disk (a 3.4 MB tmpfs holding the 2-ns case), restart to 10 ns: a clear error when a write fails, earlier results intact, and after space is freed (tmpfs grown) the restart continues and equals an uninterrupted run?
. "$(dirname "$0")/../lib.sh"
blastDone; latest; rm -f log.*; cp -r . ../ref; (cd ../ref && rm -rf [1-9]* solid postProcessing && sed -i "s/^startFrom .*/startFrom startTime;/" system/controlDict && blastEnd 10e-9 1e-9 && cellBlastFoam > log.ref 2>&1; echo "reference (from 0) rc=$?")
m=$W/mnt; mkdir -p $m; mount -t tmpfs -o size=3400k tmpfs $m; cp -a . $m/case; cd $m/case; df -k . | tail -1; snap $W/before; blastEnd 10e-9 1e-9
run 120 cellBlastFoam > $W/log.full 2>&1; fatal $W/log.full 3; echo "gone (content found nowhere): $(gone $W/before | tr '\n' ' ')"; ls -a | tr '\n' ' '; echo
cd $W; mount -o remount,size=20m $m; cd $m/case; run 120 cellBlastFoam > $W/log.after 2>&1; fatal $W/log.after 6; tail -1 $W/log.after; ls | tr '\n' ' '; echo
/usr/bin/python3 "$ROOT/tests/blast/compareRestart.py" $W/ref . --bitwise --h5 2>&1 | cut -c1-200 | tail -8; cd $W; umount $m

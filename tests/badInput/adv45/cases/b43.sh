#!/bin/bash
# b43 (class 4+5, an indentation on a FULL disk, then the space back): the smoke case (10x finer steps) copied into a 1.5 MB tmpfs; the run fails when the disk fills: an error naming the file/device, no crash, exit non-zero; the tmpfs grown to 60 MB and the run restarted (startFrom latestTime): it continues to its end and its peaks.dat equals a clean run's (bitwise)?
. "$(dirname "$0")/../lib.sh"
ind; sed -i 's/maxDepthIncrement 0.1e-6/maxDepthIncrement 0.01e-6/' constant/indenterProperties; cp -r $W/ind $W/ref; (cd $W/ref && cellIndentationFoam > log.ref 2>&1; echo "   reference rc=$?")
tiny 1500k; cp -r $W/ind $W/fs/case; cd $W/fs/case; df -k . | tail -1 | awk '{print "   tmpfs: " $4 " kB free"}'; timeout -s KILL 200 cellIndentationFoam > $W/log.full 2>&1; echo "   on the full disk: rc=$? $(grep -a -m1 -A3 'FATAL\|rror' $W/log.full | grep -av '^ *$\|^-->\|From' | tr '\n' ' ' | cut -c1-300)"; ls -a postProcessing/indentation 2>/dev/null | tr '\n' ' '; echo
cd $W; mount -o remount,size=60m $W/fs; cd $W/fs/case; latest; timeout -s KILL 200 cellIndentationFoam > $W/log.after 2>&1; echo "   after: rc=$? $(grep -a -m1 -A2 'FATAL' $W/log.after | tr '\n' ' ' | cut -c1-200)"
cmp postProcessing/indentation/peaks.dat $W/ref/postProcessing/indentation/peaks.dat && echo "   peaks.dat equal to the clean run's"; forceOk postProcessing/indentation/force.dat; cd $W

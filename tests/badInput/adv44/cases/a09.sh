#!/bin/bash
# a09 (class 2, fix19w/fix19y at an -overwrite from a MIDDLE time): a blast finished to 3 ns (writes every 1 ns); the user's own postProcessing/fsi/1e-09/coupling.dat (no header) and solidInterfaces/1e-09/interfaceMaxima.dat; -overwrite with startTime 1e-09 (the new start's segment is 1e-09): refused naming them, or written over / removed?
. "$(dirname "$0")/../lib.sh"
blast; blastEnd 3e-9 1e-9; run 150 cellBlastFoam > log.first 2>&1; echo "   first: times $(ls -d [1-9]* | tr '\n' ' ')"
P=postProcessing; mkdir -p $P/fsi/1e-09 $P/solidInterfaces/1e-09; echo "a09 my coupling table" > $P/fsi/1e-09/coupling.dat; echo "a09 my maxima" > $P/solidInterfaces/1e-09/interfaceMaxima.dat
sed -i 's/^startFrom .*/startFrom startTime;/; s/^startTime .*/startTime 1e-09;/' system/controlDict; grep -a '^startTime\|^startFrom' system/controlDict | tr '\n' ' '; echo
sums > ../s; tryf "-overwrite from 1e-09" cellBlastFoam -overwrite; echo "   times $(ls -d [1-9]* | tr '\n' ' ')"; kept "a09 my coupling table" "a09 my maxima"; nochange ../s

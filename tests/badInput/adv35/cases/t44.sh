#!/bin/bash
# t44: solidToFoam -region p / 0.orig on a finished blast case (names of a field file / a folder of the case)
. "$(dirname "$0")/../lib.sh"
blastDone; sums > ../before
for r in p 0.orig postProcessing; do solidToFoam -region $r solid/solid.h5 > log.s.$r 2>&1; echo "-region $r: rc=$? $(grep -A1 FATAL log.s.$r | tail -1 | cut -c1-150)"; done
sums | grep -v "log\." > ../after; grep -v "log\." ../before | diff - ../after | grep "^[<>]" | grep -v "0.orig/\|postProcessing/[DJU]\|postProcessing/\(pressure\|region\|sigma\|temperatureRise\|vonMises\)" | head -12; ls 2e-09 | head -20 | tr '\n' ' '
setd system/controlDict startFrom latestTime; setd system/controlDict endTime 3e-9; cellBlastFoam > log.run 2>&1; echo "restart rc=$?"; grep -A3 FATAL log.run | head -4
echo "--- region p: its fields (expected under <time>/p/):"; ls -la 1e-09/p 2e-09/p | head -3; tail -2 log.s.p

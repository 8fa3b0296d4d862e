#!/bin/bash
# CASETIMEOUT=600
# n25 (new, class 5: n02's appended row in the solid probes' log, measured by planeWave's solid measures): p8 (finished to
# 8e-9); postProcessing/solidProbes/0/solidProbes.dat + a copy of its last row with the time 8.5e-9 and every other
# number x10; planeWave -case . and incidentWindow.py. Expected: refused (rows after the run's last commit); the solid
# measures (vonMises1ns, strain1ns) taken from the hand row without a word = SILENT.
. "$(dirname "$0")/../lib.sh"
p8; f=postProcessing/solidProbes/0/solidProbes.dat; tryt 300 "(0) planeWave" planeWave -case .; grep -a -A3 'probe  region' $W/try.log | sed -n 2,3p | cut -c1-200
tail -n 1 $f | awk '{ $1 = 8.5e-09; for (i = 2; i <= NF; i++) $i = $i * 10; print }' >> $f; tail -n 1 $f | cut -c1-150; ok_ $f
tryt 300 "(a) planeWave, solidProbes.dat + a row" planeWave -case .; echo "   said: $(say 2 | cut -c1-250)"; grep -a -A3 'probe  region' $W/try.log | sed -n 2,3p | cut -c1-200; grep -a 'by 8.5e-09\|8.5e-09' $W/try.log | head -2 | cut -c1-200

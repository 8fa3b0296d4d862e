#!/bin/bash
# g20 (class 5, one damaged bit in every file the indentation wrote): a fine smoke run SIGKILLed after its first checkpoint; for each file of postProcessing/indentation (restart.h5, solid.h5, solid.xmf, force.dat, peaks.dat, materials.dat) and offsets 1/2 and 3/4 of its size, in a fresh copy, that byte xor 0x01; restart: refused naming the file, or continued with force.dat and peaks.dat equal to an uninterrupted run's?
. "$(dirname "$0")/../lib.sh"
mkdir -p $W/u; cp -r $ADV/indBase/{system,constant} $W/u/; (cd $W/u; sed -i 's/maxDepthIncrement 0.1e-6/maxDepthIncrement 0.01e-6/' constant/indenterProperties; cellIndentationFoam > log.u 2>&1)
indKilled 0.3; cd ..; mv ind k0
for f in $(cd k0; ls postProcessing/indentation/* ); do for q in 2 4; do
  rm -rf k; cp -r k0 k; cd k; n=$(stat -c %s $f); o=$(( q == 2 ? n/2 : 3*n/4 )); flip $f $o
  timeout -s KILL 100 cellIndentationFoam > log.r 2>&1; rc=$?; m=$(grep -a -m1 -A2 'FATAL\|rror' log.r | grep -av '^ *$' | tr '\n' ' ' | cut -c1-230)
  if [ $rc = 0 ]; then r=""; for g in force.dat peaks.dat; do cmp -s postProcessing/indentation/$g $W/u/postProcessing/indentation/$g && r="$r $g same" || r="$r $g DIFF"; done; echo "$f byte $o of $n: rc 0,$r"; else echo "$f byte $o of $n: rc $rc | $m"; fi; cd ..
done; done

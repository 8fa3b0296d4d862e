#!/bin/bash
# g23 (class 2+4, a read-only folder at each write of a restart): finished blast to 2 ns; in a fresh copy, one folder made read-only by a read-only bind mount (solid/, postProcessing/fsi/0, postProcessing/solidProbes, 2e-09/, the case folder itself), restart to 3 ns: a clear error naming the folder, nothing changed? then the mount removed, the same restart: equal to a clean restart's?
. "$(dirname "$0")/../lib.sh"
blastRef; cd $W/r
for t in solid postProcessing/fsi/0 postProcessing/solidProbes 2e-09 .; do
  rm -rf k; cp -r ref2 k; cd k; latest; blastEnd 3e-9 1e-9; sums > ../s; mount --bind $t $t && mount -o remount,ro,bind $t || { echo "no bind mount"; cd ..; continue; }
  timeout -s KILL 100 cellBlastFoam > ../log.r 2>&1; rc=$?; echo "$t read-only: rc $rc | $(grep -a -m1 -A2 'FATAL\|rror' ../log.r | grep -av '^ *$' | tr '\n' ' ' | cut -c1-260)"
  umount $t; nochange ../s; echo "   left: $(ls -a | grep -v '^\.\.\?$' | grep '^\.' | tr '\n' ' ')"
  timeout -s KILL 100 cellBlastFoam > ../log.r2 2>&1; echo "   writable again, restart: rc $? $(grep -a -m1 -A1 'FATAL' ../log.r2 | tr '\n' ' ' | cut -c1-200)"; [ -d 3e-09 ] && cmpRef $W/r/ref; cd ..
done

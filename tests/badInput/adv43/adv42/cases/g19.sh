#!/bin/bash
# g19 (class 5, one damaged bit in every file the blast run wrote): finished to 2 ns; for each file of 2e-09/ (fields, uniform/, .writeCommitted, polyMesh/), of solid/ and of postProcessing/ (the four logs), in a fresh copy, the byte in the middle of the file xor 0x01; restart to 3 ns: refused naming the file, or continued with results equal to a clean restart's? (rc 0 with other results: SILENT)
. "$(dirname "$0")/../lib.sh"
blastRef; cd $W/r/ref2; files=$(find 2e-09 solid postProcessing -type f | sort); cd ..
for f in $files; do
  rm -rf k; cp -r ref2 k; cd k; n=$(stat -c %s $f); flip $f $((n/2)); latest; blastEnd 3e-9 1e-9
  timeout -s KILL 100 cellBlastFoam > log.r 2>&1; rc=$?; m=$(grep -a -m1 -A2 'FATAL\|rror' log.r | grep -av '^ *$' | tr '\n' ' ' | cut -c1-230)
  if [ $rc = 0 ]; then echo "$f ($n bytes, byte $((n/2))): rc 0 $(cmpRef $W/r/ref)"; else echo "$f ($n bytes): rc $rc | $m"; fi; cd ..
done

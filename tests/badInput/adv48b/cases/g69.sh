#!/bin/bash
# g69 (class 1/5, one rank's input record damaged; written after g12's hang) pbd restart on 2 ranks to 3e-9 with processor1/2e-09/uniform/inputDigests (a) emptied, (b) replaced by processor0's, (c) cut to half its bytes (rank 0's intact): each refused on rank 1 naming the file (its bytes are not its commit's), every rank exiting within seconds; never a hang (90 s each here).
. "$(dirname "$0")/../lib.sh"
pbd; rs; f=processor1/2e-09/uniform/inputDigests; cp $f ../r0; cmp -s $f processor0/2e-09/uniform/inputDigests && echo "   (the two ranks' records are equal)" || echo "   (the two ranks' records differ)"; sums > ../s0
for v in a b c; do cp ../r0 $f; case $v in a) : > $f;; b) cp processor0/2e-09/uniform/inputDigests $f;; c) head -c $(( $(stat -c %s ../r0) / 2 )) ../r0 > $f;; esac
  tryt 90 "($v)" mpirun -np 2 cellBlastFoam -parallel; echo "   changed: $(changed ../s0)"; rm -rf processor*/3e-09; done

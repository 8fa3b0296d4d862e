#!/bin/bash
# d45 (class 5, the finished preview with one bit flipped in the restart time 2e-09: (a) uniform/fsiState (text), (b) uniform/time, (c) the binary field p (middle), (d) uniform/solidState): each restart refused naming the file (the commit marker's digests), nothing changed.
. "$(dirname "$0")/../lib.sh"
for f in uniform/fsiState uniform/time p uniform/solidState; do cd $W; rm -rf blast; bd; rs; [ -f 2e-09/$f ] || { echo "no 2e-09/$f"; continue; }; sums > ../s0; s=$(stat -c %s 2e-09/$f); flip 2e-09/$f $((s/2)); sums > ../s1
  tryt 240 "2e-09/$f bit flipped at $((s/2))" cellBlastFoam; cont; echo "   changed by the restart: $(changed ../s1)"; after; done

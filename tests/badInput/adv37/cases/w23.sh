#!/bin/bash
# w23: blast run to 2 ns, solid/solid.h5 cut to half its size, restart: refused naming the file? earlier results untouched?
. "$(dirname "$0")/../lib.sh"
blastDone; latest; blastEnd 3e-9 1e-9; s=$(stat -c %s solid/solid.h5); truncate -s $((s/2)) solid/solid.h5; contents > ../before
run 120 cellBlastFoam > log.r 2>&1; fatal log.r 4; tail -1 log.r; echo "lost: $(lost ../before | wc -l)"

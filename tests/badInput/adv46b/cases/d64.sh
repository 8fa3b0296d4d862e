#!/bin/bash
# d64 (class 4, a case path longer than PATH_MAX: the indentation case 40 folders of 120 characters deep (~4900 characters), run from inside it and by -case): refused naming the path (too long), exit non-zero without a crash trace; nothing written elsewhere.
. "$(dirname "$0")/../lib.sh"
ind; cd $W; p=$W; for i in $(seq 40); do p=$p/$(printf "%0120d" $i); done; mkdir -p $p; cp -a $W/ind/system $W/ind/constant $p/ 2>&1 | head -2; echo "path length ${#p}"
cd $p 2>/dev/null || echo "cd failed"; tryt 60 "(a) from inside" cellIndentationFoam; tryt 60 "(b) -case" cellIndentationFoam -case $p; cd $W; echo "   written: $(find $W -name force.dat | wc -l) force.dat"

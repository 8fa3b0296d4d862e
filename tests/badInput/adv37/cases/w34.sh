#!/bin/bash
# w34: ind killed at 2 s, restart.h5 cut to 60 % of its size, restart: refused naming the file, nothing lost?
. "$(dirname "$0")/../lib.sh"
indKilled 2; f=postProcessing/indentation/restart.h5; truncate -s $(( $(stat -c %s $f) * 6 / 10 )) $f; contents > ../before
run 120 cellIndentationFoam > log.r 2>&1; fatal log.r 4; tail -1 log.r; echo "lost: $(lost ../before | wc -l)"

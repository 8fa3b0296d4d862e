#!/bin/bash
# d58 (class 2, cellBlastFoam -overwrite over the finished preview SIGKILLed 3 s and 20 s after its start, then a plain restart): the earlier times and solid.h5 kept (as .<time>.overwritten or in place), the restart refused naming them and how to get them back; nothing of the earlier run lost.
. "$(dirname "$0")/../lib.sh"
for s in 3 20; do cd $W; rm -rf blast; bd; contents > ../c0; killAt $s cellBlastFoam -overwrite; echo "   after the kill: $(ls -a | tr "\n" " ")"; echo "   earlier contents lost: $(lost ../c0 | wc -l) of $(wc -l < ../c0)"
  latest; tryt 100 "   then a restart" cellBlastFoam; echo "   earlier contents lost now: $(lost ../c0 | wc -l)"; done

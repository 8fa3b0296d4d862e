#!/bin/bash
# d60 (class 4, solidToFoam -wedgeAngle odd on the finished preview, 60 s): 0, -5, 360, 1e-400, nan, 0x10, " 5": each refused naming the option and the valid range, nothing written; 180 accepted or refused by range.
. "$(dirname "$0")/../lib.sh"
bd; for a in 0 -5 360 1e-400 nan 0x10 " 5" 180; do tryt 60 "[$a]" solidToFoam -wedgeAngle "$a" solid/solid.h5; [ -d constant/solid ] && echo "      (wrote constant/solid)"; rm -rf constant/solid [0-9]*/solid; done

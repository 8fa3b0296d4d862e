#!/bin/bash
# f62 (class 4, solidToFoam -wedgeAngle at its edges): on the finished preview's solid.h5: 0, -0, 4.9e-324, 1e-300, 360, 360.00000000000006, 180: the invalid ones refused naming -wedgeAngle and its range, nothing written; the valid ones write constant/solid (removed between tries).
. "$(dirname "$0")/../lib.sh"
bd; for a in 0 -0 4.9e-324 1e-300 360 360.00000000000006 180; do tryt 60 "-wedgeAngle $a" solidToFoam -wedgeAngle $a solid/solid.h5; [ -d constant/solid ] && echo "   (wrote constant/solid and $(ls -d [0-9]*/solid 2>/dev/null | wc -l) time folders)"; rm -rf constant/solid [0-9]*/solid; done

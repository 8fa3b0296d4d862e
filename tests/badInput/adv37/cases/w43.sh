#!/bin/bash
# w43: solidToFoam -wedgeAngle at its edges: 0, -5, nan, 360, 1e400, 5deg
. "$(dirname "$0")/../lib.sh"
blastDone; for a in 0 -5 nan 360 1e400 5deg; do try "-wedgeAngle $a" solidToFoam -wedgeAngle $a solid/solid.h5; done

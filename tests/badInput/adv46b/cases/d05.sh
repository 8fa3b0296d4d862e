#!/bin/bash
# d05 (class 1, blast restart after interface settings changed one at a time: motionDistance 5e-6 -> 6e-6, motionNearest 8 -> 6, mapTolerance 0.1 -> 0.2, coupling velocityScale 1e-2 -> 2e-2): each refused naming the entry (motionDistance, motionNearest and velocityScale change the result; mapTolerance is a check only: accepting it is fine).
. "$(dirname "$0")/../lib.sh"
for e in "motionDistance  5e-6/motionDistance  6e-6" "motionNearest   8/motionNearest   6" "mapTolerance    0.1/mapTolerance    0.2" "velocityScale   1e-2/velocityScale   2e-2"; do
  cd $W; rm -rf blast; bd; rs; sed -i "s/$e/" constant/fsiProperties; n=$(grep -c "${e#*/}" constant/fsiProperties)
  tryt 240 "${e#*/} (edit found $n)" cellBlastFoam; cont; after; done

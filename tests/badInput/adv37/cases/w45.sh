#!/bin/bash
# w45: solidToFoam started while cellBlastFoam runs in the case (writing solid.h5): refused (lock), or converts a half-written file?
. "$(dirname "$0")/../lib.sh"
blast; blastEnd 8e-9 1e-9; cellBlastFoam > log.a 2>&1 & p=$!; i=0; until [ "$(committed)" -ge 2 ] || [ $i -ge 300 ]; do sleep 0.1; i=$((i+1)); done
try during solidToFoam solid/solid.h5; wait $p; echo "solver rc=$?"; tail -1 log.a

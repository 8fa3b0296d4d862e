#!/bin/bash
# c02: two cellBlastFoam at once in one case
. "$(dirname "$0")/../lib.sh"
blast; setd system/controlDict endTime 2e-8
cellBlastFoam > log.a 2>&1 & p=$!; sleep 0.5; cellBlastFoam > log.b 2>&1; echo "second rc=$?"; grep -A4 FATAL log.b | head -6; wait $p; echo "first rc=$?"; tail -1 log.a

#!/bin/bash
# v06: sod: two rhoRiemannFoam at once (endTime 0.1)
. "$(dirname "$0")/../lib.sh"
sod; sed -i 's/^endTime .*/endTime 0.1;/' system/riemannProblemDict; rhoRiemannFoam > log.a 2>&1 & p=$!; sleep 0.4; rhoRiemannFoam > log.b 2>&1; echo "second rc=$?"; grep -A1 FATAL log.b | head -2; wait $p; echo "first rc=$?"

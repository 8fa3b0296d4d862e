#!/bin/bash
# x40: sod (setRiemannProblem writes 0/p etc.): run to its end; then setRiemannProblem re-run with writeFormat binary (0/ rewritten binary, same states) and a restart with an extended endTime: accepted? then the RIGHT state changed in riemannProblemDict and setRiemannProblem re-run (0/ now another problem), restart: refused naming the initial fields?
. "$(dirname "$0")/../lib.sh"
sodDone; e=$(foamDictionary -entry endTime -value system/controlDict); latest; setd system/controlDict endTime $(/usr/bin/python3 -c "print($e*1.2)")
setd system/controlDict writeFormat binary; try "setRiemannProblem binary over a finished run" setRiemannProblem; setd system/controlDict writeFormat ascii; grep -a -m1 format 0/p
try "restart, 0/ binary" rhoRiemannFoam; grep -n "right" -A3 system/riemannProblemDict | head -5

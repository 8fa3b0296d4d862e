#!/bin/bash
# z03: sod (rhoRiemannFoam) finished: `-postProcess`, `-dry-run`, `-dry-run-write` over it: results unchanged (or refused)? then the end time raised by 20 % and a restart: continues from the old end?
. "$(dirname "$0")/../lib.sh"
sodDone; sums > ../before; t=$(ls -d [0-9]* | sort -g | tail -1); echo "end time dir $t"
try "-postProcess" rhoRiemannFoam -postProcess; echo "changed: $(changed ../before)"
try "-dry-run" rhoRiemannFoam -dry-run; echo "changed: $(changed ../before)"
try "-dry-run-write" rhoRiemannFoam -dry-run-write; echo "changed: $(changed ../before)"; echo "times: $(ls -d [0-9]* | tr '\n' ' ')"
e=$(/usr/bin/python3 -c "print(repr($t*1.2))"); sed -i "s/^endTime .*/endTime $e;/; s/^writeInterval .*/writeInterval $e;/" system/controlDict
try "restart to $e" rhoRiemannFoam; echo "times: $(ls -d [0-9]* | tr '\n' ' ')"; grep -a -m1 "^Time = \|Starting time loop" -A0 log.* 2>/dev/null | head -2

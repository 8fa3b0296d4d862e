#!/bin/bash
# g16 (class 2+3, a re-run killed at every stage of its start-up): finished blast to 2 ns; in a fresh copy for each delay d (0.03 ... 3 s), `cellBlastFoam -overwrite` SIGKILLed d s after its start; then: any earlier content lost (before the new run's first commit: none may be)? what a plain restart says; and `cellBlastFoam -overwrite` again: runs to 2 ns with logs equal to the original's?
. "$(dirname "$0")/../lib.sh"
blastDone; cd ..; mv blast orig
for d in 0.03 0.08 0.15 0.25 0.4 0.6 0.9 1.3 2 3; do
  rm -rf k; cp -r orig k; cd k; contents > ../before; killAt $d cellBlastFoam -overwrite > /dev/null
  c=$(ls -d [1-9]*/.writeCommitted 2>/dev/null | tr '\n' ' '); l=$(lost ../before | wc -l); echo "d=$d: committed now: ${c:-none}; earlier contents lost: $l; aside: $(ls -d .[0-9]* solid/.*overw* postProcessing/.*overw* 2>/dev/null | tr '\n' ' ' | cut -c1-120); lock: $(lockOf | cut -c1-40)"
  cp -r . ../kr; (cd ../kr; latest; blastEnd 3e-9 1e-9; tryf "   restart" cellBlastFoam)
  tryf "   -overwrite again" cellBlastFoam -overwrite; echo "   $(sameSeries ../orig | awk '{print $1, $2}' | tr '\n' ' ') solid.h5 $(h5same solid/solid.h5 ../orig/solid/solid.h5)"; cd ..; rm -rf kr
done

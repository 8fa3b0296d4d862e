#!/bin/bash
# q18: adv40 z31 with fix19v's NEW advice: the preview Allrun SIGKILLed in its solver, ./Allrun again: its refusal's advice ("set startFrom latestTime in system/controlDict, run in <case>: rm -f log.cellBlastFoam.running log.cellBlastFoam.status; cellBlastFoam > log.cellBlastFoam 2>&1 and, once it ended, ./Allrun again") followed word for word: the Allrun then finishes (exit 0, post-processing done), 8e-09/p equal to an uninterrupted Allrun's?
. "$(dirname "$0")/../lib.sh"
killedAllrun 3e-09; again a2; echo "---- the Allrun's refusal (log.a2):"; grep -a -v '^ *$' ../log.a2 | grep -a -A3 'Allrun: error' | head -5 | cut -c1-700; echo "----"
cmd=$(grep -a -A1 'Allrun: error' ../log.a2 | tail -1 | sed 's/^ *//'); echo "following: startFrom latestTime; $cmd"
latest; timeout -s KILL 200 bash -c "$cmd"; echo "hand run rc=$? $(tail -2 log.cellBlastFoam | tr '\n' ' ')"
again a3; echo "a3: $(grep -a "^rc=\|error" ../log.a3 | tr "\n" " ")"; ls log.* | tr '\n' ' '; echo
cp -r $ROOT/tutorials/blast/axisymmetricPreview $W/ref; (cd $W/ref && ./Allrun $PREV -endTime 8e-9 > ../log.ref 2>&1); cmp -s 8e-09/p $W/ref/8e-09/p && echo "8e-09/p equal to the uninterrupted Allrun" || echo "8e-09/p DIFFERS (or missing)"
for f in $(cd $W/ref && ls -p | grep -v / ; cd $W/ref && find postProcessing -type f); do [ -e "$f" ] || echo "   missing vs the uninterrupted Allrun: $f"; done

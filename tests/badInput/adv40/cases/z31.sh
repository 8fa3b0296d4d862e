#!/bin/bash
# z31: the preview Allrun SIGKILLed (whole group) in its solver; ./Allrun refuses with advice "startFrom latestTime ... and cellBlastFoam by hand (rm log.cellBlastFoam log.cellBlastFoam.running log.cellBlastFoam.status first)": followed word for word (the hand run's output to the terminal), then ./Allrun for the post-processing: exit 0, the solver not run again, times to 8 ns, 8e-09/p equal to an uninterrupted Allrun's?
. "$(dirname "$0")/../lib.sh"
killedAllrun 3e-09; again a2; grep -a -o "to continue a solver.*" ../log.a2 | cut -c1-250
rm log.cellBlastFoam log.cellBlastFoam.running log.cellBlastFoam.status; latest; run 200 cellBlastFoam > ../terminal.hand 2>&1; tail -1 ../terminal.hand
again a3; echo "a3 rc: $(grep -a -c 'rc=' ../log.a3) $(tail -2 ../log.a3 | tr '\n' '|' | cut -c1-200)"; ls log.* | tr '\n' ' '; echo
cp -r $ROOT/tutorials/blast/axisymmetricPreview $W/ref; (cd $W/ref && ./Allrun $PREV -endTime 8e-9 > ../log.ref 2>&1); cmp -s 8e-09/p $W/ref/8e-09/p && echo "8e-09/p equal to the uninterrupted Allrun" || echo "8e-09/p DIFFERS (or missing)"

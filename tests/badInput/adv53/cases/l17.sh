#!/bin/bash
# CASETIMEOUT=900
# l17 (new, class 4/5: OpenFOAM's debugging environment in a user's shell - FOAM_SETNAN=true fills new fields with NaN
# (uninitialised values show), FOAM_ABORT=true turns a FatalError into abort()): (a) bd restarted to 3e-9 with
# FOAM_SETNAN=true: its 3e-09/p and logs against the plain restart's (bitwise expected: every value is set before use);
# (b) the killed indentation ik restarted with FOAM_SETNAN=true against the plain one (force.dat); (c) the short preview
# with a bad input (coupling tolerance 0.5) under FOAM_ABORT=true; (d) waterPulseWall to 2e-8 with FOAM_SETNAN=true vs
# plain. Expected: (a), (b), (d) the same results (a NaN or another value = SILENT); (c) the refusal printed, rc != 0 (an
# abort's stack trace instead of the message = UNCLEAR low).
. "$(dirname "$0")/../lib.sh"
bd; rs; rm -f .runLock; cd $W; cp -a blast ref; cd ref; tryt 400 "(0) the plain restart to 3e-9" cellBlastFoam
cd $W/blast; tryt 400 "(a) the restart with FOAM_SETNAN=true" env FOAM_SETNAN=true cellBlastFoam; echo "   End $(grep -a -c '^End' $W/try.log) | 3e-09/p: $(cmp -s 3e-09/p $W/ref/3e-09/p && echo same || echo DIFFERS) | solid.h5: $(h5same solid/solid.h5 $W/ref/solid/solid.h5) | nan in 3e-09: $(grep -a -l -i nan 3e-09/* 2>/dev/null | tr '\n' ' ')"
echo "   logs: $(sameSeries $W/ref | awk '{print $1, $2}' | tr '\n' ' ')"
cd $W; rm -rf blast ref; ik; cp -a . $W/ikr; tryt 600 "(0b) the plain indentation restart" cellIndentationFoam; cd $W/ikr; tryt 600 "(b) the indentation restart with FOAM_SETNAN=true" env FOAM_SETNAN=true cellIndentationFoam
echo "   End $(grep -a -c '^End' $W/try.log) | force.dat: $(cmp -s postProcessing/indentation/force.dat $W/ind/postProcessing/indentation/force.dat && echo same || echo DIFFERS) | solid.h5: $(h5same postProcessing/indentation/solid.h5 $W/ind/postProcessing/indentation/solid.h5)"
cd $W; sb; sete constant/fsiProperties tolerance 0.5; tryt 120 "(c) tolerance 0.5 under FOAM_ABORT=true" env FOAM_ABORT=true cellBlastFoam; echo "   sig/stack $(sig) | said: $(say 2 | cut -c1-250)"
cd $W; wp 2e-8; cp 2e-08/p $W/wp.p; rm -rf [1-9]* postProcessing; tryt 300 "(d) waterPulseWall to 2e-8 with FOAM_SETNAN=true" env FOAM_SETNAN=true rhoRiemannFoam; echo "   2e-08/p: $(cmp -s 2e-08/p $W/wp.p && echo same || echo DIFFERS)"

#!/bin/bash
# q01: blast finished to 2 ns; `cellBlastFoam -postProcess -func fluidProbes` (only the probe function object, by name) and `cellBlastFoam -postProcess -latestTime`: any result changed? then a restart to 3 ns continues?
. "$(dirname "$0")/../lib.sh"
blastDone; sums > ../before
tryf "-postProcess -func fluidProbes" cellBlastFoam -postProcess -func fluidProbes; nochange ../before
tryf "-postProcess -latestTime" cellBlastFoam -postProcess -latestTime; nochange ../before
tryf "-postProcess -time 1e-09" cellBlastFoam -postProcess -time 1e-09; nochange ../before
latest; blastEnd 3e-9 1e-9; tryf "restart to 3e-9" cellBlastFoam; echo "   times: $(ls -d [0-9]* | tr '\n' ' ') solid.h5 steps $(h5steps solid/solid.h5)"

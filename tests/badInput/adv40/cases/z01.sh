#!/bin/bash
# z01: blast finished to 2 ns; `cellBlastFoam -postProcess` (an option its -help lists: function objects only) run over it, serial: does it change any result (probes, logs, times)? then a restart to 3 ns: continues (the logs' digests still hold)?
. "$(dirname "$0")/../lib.sh"
blastDone; sums > ../before
try "-postProcess" cellBlastFoam -postProcess; echo "files changed by it: $(changed ../before)"; echo "postProcessing now: $(ls postProcessing/*/ | tr '\n' ' ')"
latest; blastEnd 3e-9 1e-9; try "restart to 3e-9" cellBlastFoam; echo "times: $(ls -d [0-9]* | tr '\n' ' ')"; echo "solid.h5 steps $(h5steps solid/solid.h5), solid.xmf $(xmfsteps solid/solid.xmf)"

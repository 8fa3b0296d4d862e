#!/bin/bash
# q02: OpenFOAM's own `postProcess` utility (no -func: the controlDict's functions, i.e. fluidProbes of libfsi) over a finished blast case, then a restart to 3 ns: docs/reliability.md's guarantee for post-processing by hand
. "$(dirname "$0")/../lib.sh"
blastDone; sums > ../before
tryf "postProcess" postProcess; nochange ../before; echo "   fluidProbes/0/p: $(stat -c %s postProcessing/fluidProbes/0/p) bytes (before: $(grep -c . ../before) files listed)"
latest; blastEnd 3e-9 1e-9; tryf "restart to 3e-9" cellBlastFoam; echo "   times: $(ls -d [0-9]* | tr '\n' ' ')"

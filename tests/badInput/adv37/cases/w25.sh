#!/bin/bash
# w25: blast: an OLDER solid.h5 of the same run (saved when it had 1 step, at 1 ns) put back after the run reached 2 ns, restart from 2 ns: refused?
. "$(dirname "$0")/../lib.sh"
blast; latest; blastEnd 1e-9 1e-9; cellBlastFoam > log.1 2>&1; cp solid/solid.h5 ../old.h5; cp solid/solid.xmf ../old.xmf; blastEnd 2e-9 1e-9; cellBlastFoam > log.2 2>&1; echo "run to 2 ns rc=$?"
cp ../old.h5 solid/solid.h5; cp ../old.xmf solid/solid.xmf; blastEnd 3e-9 1e-9; run 120 cellBlastFoam > log.r 2>&1; fatal log.r 4; tail -1 log.r

#!/bin/bash
# x38: blast finished to 2 ns, then in 0/T the ".*" pattern's condition changed (zeroGradient -> fixedValue 320 K: every wall of the water held at 320 K) and, separately, 0/U's interface condition value changed (movingWallVelocity value (0 1 0)): restart to 3 ns refused naming the file and patch, or not seen?
. "$(dirname "$0")/../lib.sh"
blastDone; latest; blastEnd 3e-9 1e-9; cp 0/T ../T0; cp 0/U ../U0
sed -i 's/^\(\s*\)".\*".*/\1".*" { type fixedValue; value uniform 320; }/' 0/T; try "0/T .* fixedValue 320" cellBlastFoam; rm -rf 3e-09; cp ../T0 0/T
sed -i 's/movingWallVelocity; value uniform (0 0 0)/movingWallVelocity; value uniform (0 1 0)/' 0/U; grep -a interface 0/U; try "0/U interface value" cellBlastFoam

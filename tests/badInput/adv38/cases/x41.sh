#!/bin/bash
# x41: 0/U of the blast: the interface patch's movingWallVelocity changed to slip and the bottom's slip to noSlip after a run to 2 ns (conditions of patches other than the pulse's top), restart to 3 ns: refused naming each?
. "$(dirname "$0")/../lib.sh"
blastDone; latest; blastEnd 3e-9 1e-9; sed -i 's/^\(\s*bottom\s*\){ type slip; }/\1{ type noSlip; }/' 0/U; grep -a "bottom" 0/U; try "0/U bottom noSlip" cellBlastFoam

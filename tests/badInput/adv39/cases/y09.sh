#!/bin/bash
# y09: the solid mesh scale at its range's edges [1e-9, 1000]: 1e-9 and 1000 (in range; the cell-size check then), 9.99e-10 and 1000.001 (just out), 0, -1, 1e-3: each refused naming scale or the cell size with the range, never a crash
. "$(dirname "$0")/../lib.sh"
blast; each constant/solidProperties "scale 1e-9" "scale 1000" "scale 9.99e-10" "scale 1000.001" "scale 0" "scale -1" "scale 1e-3" "scale 1e+3" -- cellBlastFoam
ind; each constant/solidProperties "scale 1000.001" "scale 1e-10" -- cellIndentationFoam

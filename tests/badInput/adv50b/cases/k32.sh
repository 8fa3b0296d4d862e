#!/bin/bash
# k32 (class 4, units given in the wrong dimension in thermophysicalProperties and cellMeshDict): short preview: mieGruneisenCoeffs C0 "1450 [m/s]" (right), "1450 [kg]" (wrong), "[0 1 -1 0 0 0 0] 1450", rho0 "1000 [m]"; equationOfState MieGruneisen (closest word); cellMeshDict cellDiameter "16.8e-6 [s]" and "16.8 [um]". Expected: a unit refused naming the entry (numbers only) or checked against the entry's dimension and refused when wrong; never a wrong unit accepted silently while a right one is too; nothing written.
. "$(dirname "$0")/../lib.sh"
sb; F=constant/thermophysicalProperties
vals $F C0 "1450 [m/s]" "1450 [kg]" "[0 1 -1 0 0 0 0] 1450" -- cellBlastFoam
vals $F rho0 "1000 [m]" -- cellBlastFoam
vals $F equationOfState MieGruneisen -- cellBlastFoam
mdir; mv_ cellDiameter "16.8e-6 [s]" "16.8 [um]"

#!/bin/bash
# g25 (class 4, every number of the blast's dictionaries): fresh blast (endTime 1e-9); each numeric entry of constant/fsiProperties, constant/solidProperties (top level, interfaceProbe, the regions' overrides) and constant/thermophysicalProperties set in turn to nan, inf, -1, 1e400, or given twice: refused naming file, entry and range, before any output (no crash, no rc 0 with a value outside its range)?
. "$(dirname "$0")/../lib.sh"
blast; blastEnd 1e-9 1e-9
badValues constant/fsiProperties "mapTolerance motionDistance motionNearest maxIter tolerance velocityScale solidSubcycles" -- cellBlastFoam
badValues constant/solidProperties "scale explicitSafety hourglassViscosity shearViscosity heightFraction d0 C0 Gamma0" -- cellBlastFoam
badValues constant/thermophysicalProperties "rho0 C0 s Gamma0 Cv T0" -- cellBlastFoam

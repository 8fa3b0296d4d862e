#!/bin/bash
# x58: solidProperties (blast) at edges never tried: explicitSafety 1 (the stable limit itself), hourglassViscosity 0 and 1e3, shearViscosity 0.999999, interfaceProbe heightFraction 1e-12, mesh scale 1e300: each refused with the range, or run (exit 0) sensibly, no crash?
. "$(dirname "$0")/../lib.sh"
blast; each constant/solidProperties "explicitSafety 1" "hourglassViscosity 0" "hourglassViscosity 1e3" "shearViscosity 0.999999" -- cellBlastFoam
sed -i 's/heightFraction  0.75/heightFraction 1e-12/' constant/solidProperties; try "heightFraction 1e-12" cellBlastFoam; rm -rf [1-9]* solid postProcessing; cp $ADV/blastBase/axisymmetricPreview/constant/solidProperties constant/
sed -i 's/scale       1;/scale 1e300;/' constant/solidProperties; try "mesh scale 1e300" cellBlastFoam

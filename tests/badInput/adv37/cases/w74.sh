#!/bin/bash
# w74: solidProperties at the edges: explicitSafety 0, explicitSafety 1.5, hourglassViscosity -0.1, shearViscosity nan, fixed (), fixed with an unknown node set, scale 1e-6 (mesh read in um), scale 0
. "$(dirname "$0")/../lib.sh"
blast; each constant/solidProperties "explicitSafety 0" "explicitSafety 1.5" "hourglassViscosity -0.1" "shearViscosity nan" -- cellBlastFoam
cp constant/solidProperties ../sp; /usr/bin/python3 - <<'P'
import re; s=open('constant/solidProperties').read(); s=re.sub(r'\nfixed[^;]*?\);', '\nfixed ();', s, count=1, flags=re.S); open('constant/solidProperties','w').write(s)
P
try "fixed ()" cellBlastFoam; rm -rf solid postProcessing [1-9]*; cp ../sp constant/solidProperties; sed -i 's/(fixedBottom 0) (fixedBottom 1)/(fixedBotom 0) (fixedBottom 1)/' constant/solidProperties; try "fixed unknown set" cellBlastFoam
cp ../sp constant/solidProperties; sed -i 's/    scale       1; /    scale       1e-6; /' constant/solidProperties; try "scale 1e-6" cellBlastFoam; cp ../sp constant/solidProperties; sed -i 's/    scale       1; /    scale       0; /' constant/solidProperties; try "scale 0" cellBlastFoam

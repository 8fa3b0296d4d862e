#!/bin/bash
# x25: duplicates inside function-object dictionaries of controlDict: fluidProbes { fields (p); ... fields (p U); } and the probe name given twice (two fluidProbes dictionaries); and in cellMeshDict a fluid sub-dictionary given twice through an #include: refused naming both places?
. "$(dirname "$0")/../lib.sh"
blast; grep -n "fluidProbes" -A8 system/controlDict | grep -n "fields" | head -2
sed -i '0,/^\(\s*\)fields\(\s\)/s//\1fields (rho);\n\1fields\2/' system/controlDict; grep -a -n "fields" system/controlDict | head -3; try "probes fields twice" cellBlastFoam; rm -rf [1-9]* solid postProcessing; cp $ADV/blastBase/axisymmetricPreview/system/controlDict system/
awk '/^functions/{f=1} {print} f&&/^{/&&!d{print "    fluidProbes { type probes; libs (\"libsampling.so\"); fields (p); probeLocations ((0 1e-5 0)); }"; d=1}' system/controlDict > ../cd; cp ../cd system/controlDict; try "fluidProbes twice" cellBlastFoam; rm -rf [1-9]* solid postProcessing; cp $ADV/blastBase/axisymmetricPreview/system/controlDict system/

#!/bin/bash
# d65 (class 5+1, the input record of the restart time removed and an input changed: the finished preview, rm 2e-09/uniform/inputDigests, Gamma0 0.1 -> 0.2, restart): refused (the commit marker lists the record, or a time with results has no record); SILENT if it continues with Gamma0 0.2.
. "$(dirname "$0")/../lib.sh"
bd; rs; rm 2e-09/uniform/inputDigests; sed -i "s/Gamma0  0.1; /Gamma0  0.2; /" constant/thermophysicalProperties; grep -c "Gamma0  0.2" constant/thermophysicalProperties
tryt 240 "restart without the record, Gamma0 changed" cellBlastFoam; cont; after

#!/bin/bash
# d39 (class 4, thermophysicalProperties entries given twice through other include directives, blast preview, 40 s): mieGruneisenCoeffs { C0 1500; } in a file named by (a) #includeIfPresent after the coefficients, (c) #sinclude after them: refused as given twice naming both places; (d) #include before them: the later entry replaces (by design); never 1450 or 1500 chosen silently.
. "$(dirname "$0")/../lib.sh"
blast; cp constant/thermophysicalProperties ../t; printf "mieGruneisenCoeffs { C0 1500; }\n" > constant/extra
echo "#includeIfPresent \"extra\"" >> constant/thermophysicalProperties; tryt 40 "(a) #includeIfPresent" cellBlastFoam; rm -rf [1-9]* solid postProcessing
cp ../t constant/thermophysicalProperties; echo "#sinclude \"extra\"" >> constant/thermophysicalProperties; tryt 40 "(c) #sinclude after" cellBlastFoam; rm -rf [1-9]* solid postProcessing
cp ../t constant/thermophysicalProperties; sed -i "0,/^mieGruneisenCoeffs/s//#include \"extra\"\nmieGruneisenCoeffs/" constant/thermophysicalProperties; tryt 40 "(d) #include before (the later entry replaces: by design)" cellBlastFoam; grep -a -i "C0" $W/try.log | head -2; rm -rf [1-9]* solid postProcessing

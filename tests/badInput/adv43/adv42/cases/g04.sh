#!/bin/bash
# g04 (class 1, #calc): the solid's shearViscosity written as `shearViscosity #calc "0.1*2";` in constant/solidProperties. Finished to 2 ns; restart to 3 ns with (a) `#calc "0.4/2"` (the same value: continue), (b) `#calc "0.1*3"` (0.3: refused naming constant/solidProperties?)
. "$(dirname "$0")/../lib.sh"
blast; grep -n '^shearViscosity ' constant/solidProperties; sed -i 's|^shearViscosity .*|shearViscosity #calc "0.1*2";|' constant/solidProperties
run 200 cellBlastFoam > log.first 2>&1; fatal log.first 4; echo "   first run: times $(ls -d [1-9]* 2>/dev/null | tr '\n' ' ')"
[ -d 2e-09 ] || exit 0
cd ..; cp -r blast b; cd blast; latest; blastEnd 3e-9 1e-9; sed -i 's|^shearViscosity .*|shearViscosity #calc "0.4/2";|' constant/solidProperties
tryf "(a) the same value by another #calc" cellBlastFoam; echo "   times $(ls -d [1-9]* | tr '\n' ' ')"
cd ../b; latest; blastEnd 3e-9 1e-9; sed -i 's|^shearViscosity .*|shearViscosity #calc "0.1*3";|' constant/solidProperties; sums > ../s.b
tryf "(b) #calc 0.1*3" cellBlastFoam; grep -a -A3 'other inputs' $W/try.log | head -4 | cut -c1-200; nochange ../s.b

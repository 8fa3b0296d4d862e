#!/bin/bash
# b38 (class 1, blast restart after the pulse or the coupling changed where a user would change them): a blast with a planeWaveInflow top (iblast) run to 1 ns; (a) constant/inflowWave recomputed for another column (planeWave -inflow 20e-6 -Z 40e-6 -overwrite: its default -dz, not the Allrun's): the restart refused naming constant/inflowWave; (b) inflowWave back, the coupling scheme in constant/fsiProperties.allrun (an #sinclude'd file) set to aitken: refused naming it; (c) all back: continues to 2 ns?
. "$(dirname "$0")/../lib.sh"
iblast; iEnd 1e-9; cp constant/inflowWave ../wave.orig; cp constant/fsiProperties ../fsi.orig; cellBlastFoam > log.first 2>&1; echo "   first rc=$?: times $(ls -d [1-9]* | tr '\n' ' ')"; latest; iEnd 2e-9; sums > ../before
planeWave $IW -overwrite > log.pw 2>&1; echo "   planeWave -overwrite rc=$?"; tryf "(a) other inflowWave" cellBlastFoam; cp ../wave.orig constant/inflowWave
grep -a -n 'scheme\|coupling' constant/fsiProperties | head -4 | cut -c1-120; echo 'coupling { scheme aitken; }' >> constant/fsiProperties.allrun; tryf "(b) coupling scheme in fsiProperties.allrun" cellBlastFoam; nochange ../before
cp ../fsi.orig constant/fsiProperties; sed -i '$d' constant/fsiProperties.allrun; tryf "(c) all back" cellBlastFoam; echo "   times: $(ls -d [1-9]* | tr '\n' ' ')"

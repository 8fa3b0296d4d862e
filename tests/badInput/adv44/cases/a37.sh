#!/bin/bash
# a37 (class 1, a 'file' entry of T, from outside the case): waterPulseWall with its loaded patch's T a uniformFixedValue tableFile read from $W/shared/T.dat (outside the case; 293.15 K constant); run to 4e-8 s; T.dat's value 293.15 -> 303.15 K; restart to 8e-8 s: refused naming the file (T's boundary files are recorded), or continued with the other T?
. "$(dirname "$0")/../lib.sh"
mkdir -p $W/shared; printf '(\n (0 293.15)\n (1 293.15)\n)\n' > $W/shared/T.dat
cp -r "$ROOT/tutorials/verification/waterPulseWall" $W/wp; cd $W/wp; ./Allclean > /dev/null 2>&1; cp -r 0.orig 0; blockMesh > log.blockMesh 2>&1
sed -i "s|loaded          { type zeroGradient; }|loaded { type uniformFixedValue; uniformValue tableFile; uniformValueCoeffs { file \"$W/shared/T.dat\"; } value uniform 293.15; }|" 0/T; grep -a -c tableFile 0/T
sed -i "s/^endTime .*/endTime 4e-8;/" system/controlDict; run 200 rhoRiemannFoam > log.first 2>&1; fatal log.first 3; echo "   first: times $(ls -d [1-9]* | tr '\n' ' ')"
sed -i 's/293.15/303.15/g' $W/shared/T.dat; latest; sed -i "s/^endTime .*/endTime 8e-8;/" system/controlDict; sums > ../s; tryf "T.dat changed, restart" rhoRiemannFoam; echo "   times $(ls -d [1-9]* | tr '\n' ' ')"; nochange ../s

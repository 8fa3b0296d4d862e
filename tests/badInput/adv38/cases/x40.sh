#!/bin/bash
# x40: sod with its initial fields written BINARY by setRiemannProblem (writeFormat binary, the case 46fd7fe fixed), run to half its end time, restarted to the end: accepted? then 0/p put back in ASCII (foamFormatConvert on a copy: same values and conditions) and a restart with a later end: accepted, not refused as a changed initial condition?
. "$(dirname "$0")/../lib.sh"
cp -r "$ROOT/tutorials/verification/sodIdealGas" "$W/sod"; cd "$W/sod"; ./Allclean > /dev/null 2>&1; cp -r 0.orig 0; blockMesh > log.blockMesh 2>&1
e=$(sed -n "s/^endTime *\([^;]*\);.*/\1/p" system/riemannProblemDict); h=$(/usr/bin/python3 -c "print($e/2)"); echo "endTime $e"
sed -i 's/^writeFormat .*/writeFormat binary;/' system/controlDict; setRiemannProblem > log.set 2>&1 || tail -3 log.set; grep -a -m1 format 0/p
sed -i "s/^endTime .*/endTime $h;/; s/^writeInterval .*/writeInterval $h;/" system/controlDict; run 100 rhoRiemannFoam > log.1 2>&1; tail -1 log.1; fatal log.1 3
sed -i "s/^endTime .*/endTime $e;/; s/^startFrom .*/startFrom latestTime;/" system/controlDict; run 100 rhoRiemannFoam > log.2 2>&1; tail -1 log.2; fatal log.2 4
cp -r . ../conv; (cd ../conv && sed -i 's/^writeFormat .*/writeFormat ascii;/' system/controlDict && foamFormatConvert -time 0 > log.conv 2>&1 || tail -2 log.conv); cp ../conv/0/p 0/p; grep -a -m1 format 0/p
sed -i "s/^endTime .*/endTime $(/usr/bin/python3 -c "print($e*1.2)");/" system/controlDict; run 100 rhoRiemannFoam > log.3 2>&1; tail -1 log.3; fatal log.3 4

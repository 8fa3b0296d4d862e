#!/bin/bash
# y11: fixedValue conditions (fix19t keeps their value): 0/T interface fixedValue 293.15 run to 2 ns, restart to 3 ns after (a) value written 2.9315e2 (same): accepted? (b) 293.15 + 1e-9 K: refused naming it? (c) the fixedValue replaced by uniformFixedValue constant 293.15 (the same condition, other type): ?
. "$(dirname "$0")/../lib.sh"
blast; sed -i 's/^\( *\)".\*" *{ type zeroGradient; }/\1".*" { type zeroGradient; }\n    interface { type fixedValue; value uniform 293.15; }/' 0/T; run 120 cellBlastFoam > log.first 2>&1; tail -1 log.first; fatal log.first 3
latest; blastEnd 3e-9 1e-9; cp -r . ../keep
sed -i 's/value uniform 293.15;/value uniform 2.9315e2;/' 0/T; try "(a) 2.9315e2" cellBlastFoam
rm -rf $W/blast; cp -r ../keep $W/blast; cd $W/blast; sed -i 's/value uniform 293.15;/value uniform 293.150000001;/' 0/T; try "(b) 293.150000001" cellBlastFoam
rm -rf $W/blast; cp -r ../keep $W/blast; cd $W/blast; sed -i 's/interface { type fixedValue; value uniform 293.15; }/interface { type uniformFixedValue; uniformValue constant 293.15; }/' 0/T; try "(c) uniformFixedValue constant 293.15" cellBlastFoam

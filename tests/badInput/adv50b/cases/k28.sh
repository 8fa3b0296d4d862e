#!/bin/bash
# k28 (class 4, coupling words valid alone but not together, r-z only entries): short preview: (a) scheme explicitStaggered with predictor extrapolated (the guide: extrapolated for iterative schemes only); (b) IQNILS with reuse -1 and reuse 2.5; aitken with initialRelaxation 0, 1, 1.0000000000000002; (c) interface map projection (r-z: faces only) and pressureQuadrature 4 (r-z: 1 only); (d) load mappedForces with pressureQuadrature 2. Expected: each combination the guide excludes refused naming both entries (or a warning naming them); never accepted without a word.
. "$(dirname "$0")/../lib.sh"
sb; F=constant/fsiProperties; cp $F $W/f0
sete $F scheme explicitStaggered > /dev/null; fsiSet predictor extrapolated > /dev/null; tryt 150 "(a) explicitStaggered + extrapolated" cellBlastFoam; grep -a -i -m2 'warn\|predictor' $W/try.log | cut -c1-200 | sed 's/^/   log: /'; rm -rf [1-9]* solid postProcessing
cp $W/f0 $F; sete $F scheme IQNILS > /dev/null; fsiSet reuse 0 > /dev/null; vals $F reuse -1 2.5 -- cellBlastFoam
cp $W/f0 $F; sete $F scheme aitken > /dev/null; fsiSet initialRelaxation 0.1 > /dev/null; vals $F initialRelaxation 0 1 1.0000000000000002 -- cellBlastFoam
cp $W/f0 $F; sed -i 's/^ *load .*/    load pressure;\n    map projection;/' $F; tryt 150 "(c1) map projection in r-z" cellBlastFoam; rm -rf [1-9]* solid postProcessing
cp $W/f0 $F; sed -i 's/^ *load .*/    load pressure;\n    pressureQuadrature 4;/' $F; tryt 150 "(c2) pressureQuadrature 4 in r-z" cellBlastFoam; rm -rf [1-9]* solid postProcessing
cp $W/f0 $F; sed -i 's/^ *load .*/    load mappedForces;\n    pressureQuadrature 2;/' $F; tryt 150 "(d) mappedForces + pressureQuadrature 2" cellBlastFoam; grep -a -i -m2 'warn\|quadrature' $W/try.log | cut -c1-200 | sed 's/^/   log: /'

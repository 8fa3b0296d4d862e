#!/bin/bash
# d03 (class 1, blast restart after fvSolution riemann/riemannSolver HLLC -> HLL, and after comments/whitespace only): (b) refused naming system/fvSolution and the entry; (a) a comment and blank lines added to fvSolution and fvSchemes, indentation changed: accepted (refusing it is UNCLEAR low).
. "$(dirname "$0")/../lib.sh"
bd; rs; cp system/fvSolution ../fvS; sums > ../s0
sed -i "s/riemannSolver   HLLC;/riemannSolver   HLL;/" system/fvSolution; grep -c "riemannSolver   HLL;" system/fvSolution
tryt 240 "(b) HLL" cellBlastFoam; cont; echo "   changed: $(changed ../s0)"
cp ../fvS system/fvSolution; sed -i "s/^    riemannSolver   HLLC;/\t\triemannSolver HLLC ; \/\/ a comment of mine\n\n/" system/fvSolution; echo "// my note" >> system/fvSchemes; echo >> system/fvSchemes
tryt 240 "(a) comments and whitespace only" cellBlastFoam; cont; after

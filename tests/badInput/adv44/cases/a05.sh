#!/bin/bash
# a05 (class 1 + decomposePar/reconstructPar): a 2-rank blast run to 2 ns, reconstructPar; (a) the membrane's C10 changed in constant/solidProperties, then a SERIAL restart from the reconstructed 2e-09 to 3 ns: refused naming solidProperties, or continued with the other material? (b) the change undone: the serial restart continues (or refused with a clear reason)?
. "$(dirname "$0")/../lib.sh"
pblastDone; echo "   2-rank run: processor1 $(ls -d processor1/[1-9]* | xargs -n1 basename | tr '\n' ' ')"; run 120 reconstructPar > log.reconstructPar 2>&1; echo "   reconstructed: $(ls -d [1-9]* | tr '\n' ' ')"
latest; blastEnd 3e-9 1e-9; cp constant/solidProperties ../sp.orig; sed -i 's|^\( *#include "$PROJECT_DIR/etc/caseDicts/cellMaterials/[a-zA-Z0-9]*"\)|\1\n    membrane { C10 1666.7; }|' constant/solidProperties; echo "   edit: $(grep -a -A1 '#include' constant/solidProperties | tr -s ' ' | tr '\n' ' ')"
sums > ../s; tryf "(a) C10 of the membrane changed, serial restart" cellBlastFoam; grep -a -A2 'other inputs\|changed' $W/try.log | head -3 | cut -c1-200; echo "   times $(ls -d [1-9]* | tr '\n' ' ')"; nochange ../s
cp ../sp.orig constant/solidProperties; tryf "(b) unchanged, serial restart" cellBlastFoam; echo "   times $(ls -d [1-9]* | tr '\n' ' '); solid.h5 steps $(h5steps solid/solid.h5)"

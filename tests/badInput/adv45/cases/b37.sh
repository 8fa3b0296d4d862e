#!/bin/bash
# b37 (class 1, an indentation restart with changed inputs of every kind, one at a time after a kill): radius, penaltyFactor, holdGrowth (a stepping entry), tolerance, row A's depth (already run), the cytoplasm's C10 given through an #include from a unicode-named folder (constant/matériaux/set): each refused naming the file, the entry (and row); nothing changed by a refusal; everything back: continues to its end?
. "$(dirname "$0")/../lib.sh"
ind; mkdir -p "constant/matériaux"; echo 'cytoplasm { C10 1.67; }' > "constant/matériaux/set"; sed -i 's|^\( *\)#include "$PROJECT_DIR/etc/caseDicts/cellMaterials/textFactor4"|&\n\1#include "matériaux/set"|' constant/solidProperties
grep -a -q 'matériaux' constant/solidProperties || echo "   (the include line not added)"; cp constant/indenterProperties ../ip.orig
sed -i 's/maxDepthIncrement 0.1e-6/maxDepthIncrement 0.01e-6/' constant/indenterProperties; cp constant/indenterProperties ../ip.fine
cellIndentationFoam > log.first 2>&1 & p=$!; waitFor 120 test -f postProcessing/indentation/restart.h5; sleep 1; kill -KILL $p; wait $p 2>/dev/null; latest; echo "   killed: force rows $(grep -vc '^#' postProcessing/indentation/force.dat); first rc: $(grep -a -m1 FATAL log.first)"; sums > ../before
for e in "radius 20e-6" "penaltyFactor 11" "holdGrowth 1.4" "tolerance 2e-9"; do cp ../ip.fine constant/indenterProperties; sete constant/indenterProperties ${e%% *} ${e#* }; tryf "($e)" cellIndentationFoam; done
cp ../ip.fine constant/indenterProperties; sed -i 's/^\( *(A *load *0.3e-6 *\)0.3e-6 *)/\10.31e-6)/' constant/indenterProperties; grep -a -c '0.31e-6' constant/indenterProperties | sed 's/^/   row A edited: /'; tryf "(row A depth)" cellIndentationFoam
cp ../ip.fine constant/indenterProperties; echo 'cytoplasm { C10 1.7; }' > "constant/matériaux/set"; tryf "(C10 via matériaux/set)" cellIndentationFoam; nochange ../before
echo 'cytoplasm { C10 1.67; }' > "constant/matériaux/set"; tryf "(all back)" cellIndentationFoam; forceOk postProcessing/indentation/force.dat

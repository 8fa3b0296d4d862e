#!/bin/bash
# CASETIMEOUT=600
# n15 (new, class 4/1: OpenFOAM v1912's #eval in our dictionaries - an entry computed by the reader that our checks see as
# text): (a) constant/fsiProperties coupling tolerance `#eval{ 0.5 }` (outside (0, 0.1]) and `#eval{ 2e-4 }` (valid):
# the short preview; (b) controlDict.allrun `endTime #eval{ -1e-9 };` (negative); (c) indenterProperties radius
# `#eval{ 0 }`; (d) cellMeshDict.allrun `membraneLayers #eval{ 21 };` (range [1, 20]); (e) bd finished at 2e-9 with
# shearViscosity 0.2; restart to 3e-9 with shearViscosity `#eval{ 0.2 }` (the same value) and `#eval{ 0.3 }` (another).
# Expected: each out-of-range value refused naming file, entry and range (or #eval refused as not a number, naming it);
# a value outside the range taken (the run goes on with tolerance 0.5 / membraneLayers 21) = SILENT; (e) the same value
# taken, another refused as changed.
. "$(dirname "$0")/../lib.sh"
sb; cp -a . $W/s0; fsiSet tolerance '#eval{ 0.5 }'; tryt 200 "(a) tolerance #eval{ 0.5 }" cellBlastFoam; echo "   End $(grep -a -c '^End' $W/try.log) | said: $(say 2 | cut -c1-250)"
cd $W; rm -rf blast; cp -a s0 blast; cd blast; fsiSet tolerance '#eval{ 2e-4 }'; tryt 200 "(a2) tolerance #eval{ 2e-4 }" cellBlastFoam; echo "   End $(grep -a -c '^End' $W/try.log) | said: $(say 2 | cut -c1-250)"
cd $W; rm -rf blast; cp -a s0 blast; cd blast; sed -i '/^endTime/d' system/controlDict.allrun; echo 'endTime #eval{ -1e-9 };' >> system/controlDict.allrun; tryt 200 "(b) endTime #eval{ -1e-9 }" cellBlastFoam; echo "   End $(grep -a -c '^End' $W/try.log) | said: $(say 2 | cut -c1-250) | times $(ls -d [0-9]* | tr '\n' ' ')"
cd $W; ind; sed -i 's/^\( *radius *\)[^;]*;/\1#eval{ 0 };/' constant/indenterProperties; grep -n 'radius' constant/indenterProperties | head -2; tryt 200 "(c) indenter radius #eval{ 0 }" cellIndentationFoam; echo "   End $(grep -a -c '^End' $W/try.log) | said: $(say 2 | cut -c1-250)"
cd $W; mdir; mset membraneLayers '#eval{ 21 }'; tryt 200 "(d) membraneLayers #eval{ 21 }" cellMesh; echo "   said: $(say 2 | cut -c1-250) | $(grep -a -i 'layers' $W/try.log | head -n 1 | cut -c1-120)"
cd $W; bd; grep -n 'shearViscosity ' constant/solidProperties | head -2; sete constant/solidProperties shearViscosity '#eval{ 0.2 }' 2>/dev/null || sed -i '0,/^\( *shearViscosity *\)[^;]*;/s//\1#eval{ 0.2 };/' constant/solidProperties; grep -n 'shearViscosity ' constant/solidProperties | head -2
rs; rm -f .runLock; tryt 300 "(e) restart with the same shearViscosity through #eval" cellBlastFoam; echo "   End $(grep -a -c '^End' $W/try.log) | said: $(say 2 | cut -c1-250)"
cd $W; rm -rf blast; bd; sed -i '0,/^\( *shearViscosity *\)[^;]*;/s//\1#eval{ 0.3 };/' constant/solidProperties; rs; rm -f .runLock; tryt 300 "(e2) restart with shearViscosity #eval{ 0.3 }" cellBlastFoam; echo "   End $(grep -a -c '^End' $W/try.log) | said: $(say 2 | cut -c1-250)"

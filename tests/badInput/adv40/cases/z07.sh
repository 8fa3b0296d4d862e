#!/bin/bash
# z07: the material set included from OUTSIDE the case by an absolute #include (a user's copy of etc/caseDicts/cellMaterials/textFactor4 in another folder): (a) blast run to 2 ns, a number of the outside file changed, restart to 3 ns; (b) indentation killed after its first checkpoint, the same edit, restart: refused naming the material (and the file) or continued with the changed material?
. "$(dirname "$0")/../lib.sh"
mkdir -p $W/mine; cp "$ROOT/etc/caseDicts/cellMaterials/textFactor4" $W/mine/cellMats
blast; sed -i "s|#include \"\$PROJECT_DIR/etc/caseDicts/cellMaterials/textFactor4\"|#include \"$W/mine/cellMats\"|" constant/solidProperties; grep -n 'include' constant/solidProperties | head -2
cellBlastFoam > log.first 2>&1; echo "first run: $(tail -1 log.first)"
n=$(grep -n -m1 -E '^\s+C10\s' $W/mine/cellMats | cut -d: -f1); echo "edit line $n: $(sed -n ${n}p $W/mine/cellMats)"; cp $W/mine/cellMats $W/mine/cellMats.orig
sed -i "${n}s/C10\(\s*\)\([0-9.e+-]*\)/C10\1200/" $W/mine/cellMats; echo "   now: $(sed -n ${n}p $W/mine/cellMats)"
latest; blastEnd 3e-9 1e-9; tryf "(a) blast restart" cellBlastFoam; echo "   times: $(ls -d [1-9]* | tr '\n' ' ')"
cp $W/mine/cellMats.orig $W/mine/cellMats
ind; sed -i 's/maxDepthIncrement 0.1e-6/maxDepthIncrement 0.01e-6/' constant/indenterProperties; sed -i "s|#include \"\$PROJECT_DIR/etc/caseDicts/cellMaterials/textFactor4\"|#include \"$W/mine/cellMats\"|" constant/solidProperties; grep -c "$W/mine" constant/solidProperties
cellIndentationFoam > log.first 2>&1 & p=$!; waitFor 60 test -f postProcessing/indentation/restart.h5; sleep 0.3; kill -KILL $p; wait $p 2>/dev/null; latest
sed -i "${n}s/C10\(\s*\)\([0-9.e+-]*\)/C10\1200/" $W/mine/cellMats; tryf "(b) indentation restart" cellIndentationFoam

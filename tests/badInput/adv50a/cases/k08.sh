#!/bin/bash
# CASETIMEOUT=900
# k08 (adv49b i16, i01 / fix19f's writtenText and the entry's file varied): whole-number entries written as users write
# them, in other dictionaries and tools: (a) cellMeshDict.allrun `maxElements 1e6;` (the documented default written with
# an exponent), `maxElements 2e6;`, `membraneLayers 2.0;`, `membraneLayers 0x2;`; (b) fsiProperties coupling `maxIter 3e1;`,
# `maxIter 30.0;`, `solidSubcycles +4;`, interface `motionNearest 1E2;`; (c) the same solidSubcycles 1e3 written on the
# line after its keyword; (d) meshType given through an #include'd file in a quarter3D cellMeshDict ("unstructured"),
# and `mode quarter3D;` given in cellMeshDict.allrun of the r-z dictionary with `meshType unstructured;` in the main
# file. Each accepted (whole values, the run or mesh starts) or refused rc 1 quoting the text as written and naming the
# file and line where it is given; never a value the user did not write, never the wrong file.
. "$(dirname "$0")/../lib.sh"
for kv in "maxElements 1e6" "maxElements 2e6" "membraneLayers 2.0" "membraneLayers 0x2"; do mdir; set -- $kv; mset $1 $2; cm "" 120; echo "   cell.msh: $(ls constant/cell.msh 2>/dev/null || echo none)"; done
cd $W; blast; short; rm -f .runLock; cp constant/fsiProperties ../f0
for kv in "maxIter 3e1" "maxIter 30.0" "solidSubcycles +4"; do cp ../f0 constant/fsiProperties; set -- $kv; fsiSet $1 "$2" > /dev/null
  tryt 120 "(b) coupling $1 $2" cellBlastFoam; echo "   ran: $(ls -d [1-9]* 2>/dev/null | tr '\n' ' ')| msg: $(msg 3 | cut -c1-400)"; rm -rf [1-9]* solid postProcessing .runLock; done
cp ../f0 constant/fsiProperties; subset constant/fsiProperties interface motionNearest 1E2 > /dev/null; tryt 120 "(b) interface motionNearest 1E2" cellBlastFoam; echo "   ran: $(ls -d [1-9]* 2>/dev/null | tr '\n' ' ')| msg: $(msg 3 | cut -c1-400)"; rm -rf [1-9]* solid postProcessing .runLock
cp ../f0 constant/fsiProperties; sed -i '0,/^coupling/{n;s/^{/{\n    solidSubcycles\n        1e3;/}' constant/fsiProperties; grep -n -A1 'solidSubcycles' constant/fsiProperties | head -2 | tr '\n' ' '; echo
tryt 120 "(c) solidSubcycles on one line, 1e3 on the next" cellBlastFoam; echo "   msg: $(msg 3 | cut -c1-400)"; rm -rf [1-9]* solid postProcessing .runLock
mdir quarter3D; echo 'meshType unstructured;' > system/meshTypeFile; sed -i '/^#sinclude/i #include "meshTypeFile"' system/cellMeshDict; grep -n 'include' system/cellMeshDict | tr '\n' ' '; echo; cm "" 120
mdir; mset mode quarter3D; sed -i '/^#sinclude/i meshType unstructured;' system/cellMeshDict; grep -n '^mode\|^meshType\|include' system/cellMeshDict system/cellMeshDict.allrun | tr '\n' ' '; echo; cm "" 120

#!/bin/bash
# z24: resources through calibrateCell: meshSizeFactor 0.01 (the cell meshes 1.4/0.01 = 140 times finer: about 1e4 times the elements) -> refused before any forward run (cellMesh's estimate or the range), within 60 s, naming the entry?
. "$(dirname "$0")/../lib.sh"
cal; sed -i 's/^meshSizeFactor .*/meshSizeFactor 0.01;/' system/calibrationDict; try "meshSizeFactor 0.01" calibrateCell -work $W/work; ls $W/work 2>/dev/null | head -3

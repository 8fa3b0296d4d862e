#!/bin/bash
# k46 (class 6, the orthogonal O-grid near maxCells): quarter hex with hexCoeffs maxCells set just above the straight count of a 30 um box at lateral 0.5 um (the count from the straight run's refusal with maxCells 1), then oGrid orthogonal at that size, then maxCells one below the count with orthogonal. Expected: the count refused identically for straight and orthogonal (the same cells); the accepted orthogonal run ends within 480 s or is stopped by a limit that names itself.
. "$(dirname "$0")/../lib.sh"
qm "" "lateralSize 0.5e-6; maxCells 1;"; cm; lb=$(grep -a -o 'at least [0-9.]* cells' $W/try.log | head -1 | awk '{print $3}'); n=$(/usr/bin/python3 -c "import math,sys; print(math.ceil(float(sys.argv[1])))" ${lb:-0}); echo "   lower bound named: $lb -> $n"
qm "" "lateralSize 0.5e-6; maxCells $n;"; cm; e=$(grep -a -o '[0-9][0-9]* cells, more than\|[0-9][0-9]* hexahedra' $W/try.log | head -1 | awk '{print $1}'); echo "   exact count named: ${e:-none} $(grep -a -m1 -i 'cells' $W/try.log | cut -c1-160)"; [ -n "$e" ] || e=$n
qm "" "lateralSize 0.5e-6; maxCells $e;"; cm; grep -a -i -m1 'hexahedra' $W/try.log | cut -c1-120
qm "" "lateralSize 0.5e-6; maxCells $e; oGrid orthogonal;"; cm "" 480; grep -a -i -m2 'hexahedra\|sweep' $W/try.log | cut -c1-160
qm "" "lateralSize 0.5e-6; maxCells $((e-1)); oGrid orthogonal;"; cm

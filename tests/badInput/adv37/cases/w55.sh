#!/bin/bash
# w55: cellMesh started while cellBlastFoam runs in the case: refused (lock) and constant/cell.msh of the running case kept?
. "$(dirname "$0")/../lib.sh"
blast; blastEnd 8e-9 1e-9; md5sum constant/cell.msh > ../m; cellBlastFoam > log.a 2>&1 & p=$!; sleep 1; try during cellMesh; md5sum -c ../m >/dev/null && echo "cell.msh kept"; wait $p; echo "solver rc=$?"

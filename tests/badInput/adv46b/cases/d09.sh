#!/bin/bash
# d09 (class 1, must be ACCEPTED: indentation restart after cellMesh re-run with the same cellMeshDict): continues to the end if the mesh bytes are the same (refusal = UNCLEAR low); a refusal naming the mesh is right if they differ.
. "$(dirname "$0")/../lib.sh"
ik; md5sum constant/cell.msh > ../m
tryt 120 "cellMesh again" cellMesh; echo "   cell.msh: $(md5sum -c ../m 2>&1 | awk "{print \$2}")"
tryt 200 "restart" cellIndentationFoam; cont; after

#!/bin/bash
# d07 (class 1, must be ACCEPTED: blast restart after cellMesh re-run with the same dictionary): the mesh file is rewritten with the same content (or not): if its bytes are the same, the restart continues; refusing it is UNCLEAR (low); if gmsh writes other bytes, a refusal naming cell.msh is right.
. "$(dirname "$0")/../lib.sh"
bd; rs; md5sum constant/cell.msh constant/polyMesh/* > ../m
tryt 120 "cellMesh again, same dictionary" cellMesh; echo "   mesh files: $(md5sum -c ../m 2>&1 | awk "{print \$2}" | sort | uniq -c | tr "\n" " ")"
tryt 240 "restart" cellBlastFoam; cont; after

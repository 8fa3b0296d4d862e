#!/bin/bash
# o09: cellMesh re-run in a case with results (mesh changed under results)
. "$(dirname "$0")/../lib.sh"
indDone; setd system/cellMeshDict nucleusSize 0.7e-6; cellMesh 2>&1 | tail -3; echo "rc=${PIPESTATUS[0]}"

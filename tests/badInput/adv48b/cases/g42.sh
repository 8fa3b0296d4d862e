#!/bin/bash
# g42 (class 4/6, cellMesh's maxElements beyond a 32-bit label) the prepared preview's system/cellMeshDict with maxElements 0, -1, 1.5, 2147483648, 4294967297 (1 modulo 2^32), 1e10, 1e300: each refused naming maxElements, the value and the valid range, or (a valid limit above the mesh) meshed as before; never a wrapped limit ("more than maxElements 1").
. "$(dirname "$0")/../lib.sh"
blast; each system/cellMeshDict "maxElements 0" "maxElements -1" "maxElements 1.5" "maxElements 2147483648" "maxElements 4294967297" "maxElements 1e10" "maxElements 1e300" -- cellMesh

#!/bin/bash
# k01 (class 4, cellMesh structuredSmoothing elliptic on the centred spheroid): the axisymmetric structured mesh with `structuredSmoothing elliptic;` and nucleusShape centredSpheroid (the user guide: refused, scaledCell only); (b) the same in quarter3D. Expected: a FATAL IO ERROR naming the file, the entry and the valid combination, rc != 0, the existing cell.msh of a good run kept.
. "$(dirname "$0")/../lib.sh"
mdir; mset meshType structured; mset nucleusShape scaledCell; cm > /dev/null; echo "   good run: $(msh)"
mset nucleusShape centredSpheroid; mset structuredSmoothing elliptic; cmk "(a) axisymmetric centredSpheroid elliptic"
qm; mset nucleusShape scaledCell; cm > /dev/null; mset nucleusShape centredSpheroid; mset structuredSmoothing elliptic; cmk "(b) quarter3D centredSpheroid elliptic"

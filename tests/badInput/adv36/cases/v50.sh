#!/bin/bash
# v50: duplicates: system/cellMeshDict nucleusSize given twice (0.8e-6 then 0.7e-6), then cellMesh
. "$(dirname "$0")/../lib.sh"
ind; sed -i 's/^\( *nucleusSize *[0-9.e-]*;\)/\1 nucleusSize 0.7e-6;/' system/cellMeshDict; grep -n nucleusSize system/cellMeshDict | cut -c1-80; cellMesh > log.cm 2>&1; rc=$?; grep -a -A3 FATAL log.cm | head -5 | cut -c1-300; echo "rc=$rc"

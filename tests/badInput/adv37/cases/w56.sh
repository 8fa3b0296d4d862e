#!/bin/bash
# w56: cellMesh -dict pointing at a missing file, at a directory, at the controlDict (another dictionary)
. "$(dirname "$0")/../lib.sh"
ind; try missing cellMesh -dict system/nothere; try dir cellMesh -dict system; try controlDict cellMesh -dict system/controlDict

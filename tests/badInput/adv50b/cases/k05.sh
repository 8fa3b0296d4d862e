#!/bin/bash
# k05 (class 4, the new entries in the wrong dictionary): oGrid in fluid{} outside hexCoeffs, oGrid at the top level, structuredSmoothing inside fluid{}, structuredSmoothing inside hexCoeffs. Expected: each refused naming the entry and where it belongs (as axialSize outside hexCoeffs is); nothing written.
. "$(dirname "$0")/../lib.sh"
qm; cm > /dev/null; echo "   good run: $(msh)"
qm "oGrid orthogonal;"; cmk "(a) oGrid in fluid{}"
qm; mset oGrid orthogonal; cmk "(b) oGrid at the top level"
qm "structuredSmoothing elliptic;"; cmk "(c) structuredSmoothing in fluid{}"
qm "" "structuredSmoothing elliptic;"; cmk "(d) structuredSmoothing in hexCoeffs"

#!/bin/bash
# k02 (class 4, structuredSmoothing with a mesh that is not structured): `structuredSmoothing elliptic;` with the axisymmetric default meshType unstructured (gmsh's quads; the user guide: "structured meshes"), and (b) with meshType given as unstructured explicitly. Expected: refused naming both entries, or the log saying the smoothing is not applied; never a mesh written as if smoothed without a word.
. "$(dirname "$0")/../lib.sh"
mdir; mset nucleusShape scaledCell; cm > /dev/null; echo "   good run: $(msh)"; cp constant/cell.msh $W/plain.msh
mset structuredSmoothing elliptic; cmk "(a) unstructured (default) + elliptic"; echo "   log mentions smoothing: $(grep -a -i -m2 'smooth\|elliptic\|winslow' $W/try.log | cut -c1-200 | tr '\n' '|')"
cmp -s constant/cell.msh $W/plain.msh && echo "   cell.msh identical to the unsmoothed one"
mset meshType unstructured; cmk "(b) meshType unstructured + elliptic"; echo "   log mentions smoothing: $(grep -a -i -m2 'smooth\|elliptic\|winslow' $W/try.log | cut -c1-200 | tr '\n' '|')"

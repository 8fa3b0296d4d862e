#!/bin/bash
# k03 (class 4, structuredSmoothing values): Elliptic, winslow, 1, "elliptic elliptic" (two tokens), an empty value, "none none", and "elliptic" written with a unit [m], in the structured scaledCell axisymmetric mesh. Expected: each refused naming the file, the entry, the valid words (none elliptic) and for Elliptic the closest; meshes of the good run kept.
. "$(dirname "$0")/../lib.sh"
mdir; mset meshType structured; mset nucleusShape scaledCell
mv_ structuredSmoothing Elliptic winslow 1 "elliptic elliptic" "" "none none" "elliptic [m]"

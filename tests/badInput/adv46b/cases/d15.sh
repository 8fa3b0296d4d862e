#!/bin/bash
# d15 (class 1 control, must be ACCEPTED: the plain restart of the finished preview copied with cp -a, endTime 3e-9, writeInterval 0.5e-9, a comment added to controlDict): continues, writes 2.5e-09 and 3e-09.
. "$(dirname "$0")/../lib.sh"
bd; latest; blastEnd 3e-9 0.5e-9; echo "// a comment" >> system/controlDict
tryt 240 "restart" cellBlastFoam; cont; after

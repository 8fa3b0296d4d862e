#!/bin/bash
# CASETIMEOUT=600
# p20 (new, class 2: solidToFoam's outputs over a user's files of the same names): the finished preview bd with (a) a
# user's constant/solid/notes.txt and constant/solid/polyMesh/points (a user's own region mesh), (b) a user's
# 1e-09/solid/notes.txt, (c) after a first solidToFoam, a user's edit of constant/solid/polyMesh/boundary kept? (a second
# solidToFoam). Expected: refused naming the user's files (or written beside them without removing them); the user's
# files removed or replaced without a word = DATALOSS.
. "$(dirname "$0")/../lib.sh"
bd; rm -rf constant/solid; mark constant/solid/notes.txt; mark constant/solid/polyMesh/points
tryt 120 "(a) solidToFoam with a user's constant/solid/notes.txt and polyMesh/points" solidToFoam solid/solid.h5; echo "   said: $(msg 3 | cut -c1-250)"; kept_ constant/solid/notes.txt; kept_ constant/solid/polyMesh/points
rm -rf constant/solid; mark 1e-09/solid/notes.txt
tryt 120 "(b) solidToFoam with a user's 1e-09/solid/notes.txt" solidToFoam solid/solid.h5; echo "   said: $(msg 3 | cut -c1-250)"; kept_ 1e-09/solid/notes.txt
rm -rf constant/solid 1e-09/solid; tryt 120 "(c0) solidToFoam" solidToFoam solid/solid.h5; echo "# the user's note" >> constant/solid/polyMesh/boundary; sum0=$(md5sum constant/solid/polyMesh/boundary)
tryt 120 "(c) a second solidToFoam over the user's edited boundary" solidToFoam solid/solid.h5; echo "   said: $(msg 3 | cut -c1-250) | boundary: $([ "$(md5sum constant/solid/polyMesh/boundary)" = "$sum0" ] && echo kept || echo replaced)"

#!/bin/bash
# i30 (class 2/DATALOSS, Allclean and Allrun through a link from another directory): a folder of the user's ($W/user: 0/U,
# constant/polyMesh/points, postProcessing/notes.txt, log.mine, VTK/x.vtk, a time directory 1e-09/p) holding a symbolic link
# Allclean -> the preview copy's Allclean (then Allrun likewise): running ./Allclean there cleans the preview (or refuses),
# never the user's folder: every user file kept. Also `bash <case>/Allclean` from $W/user (a relative $0).
. "$(dirname "$0")/../lib.sh"
bd; cp "$ROOT/tutorials/blast/axisymmetricPreview/Allclean" .; C=$PWD; mkdir -p $W/user/0 $W/user/constant/polyMesh $W/user/postProcessing $W/user/VTK $W/user/1e-09; cd $W/user
for f in 0/U constant/polyMesh/points postProcessing/notes.txt log.mine VTK/x.vtk 1e-09/p; do echo "user's $f" > $f; done; find . -type f | sort > ../u0
ln -s $C/Allclean Allclean; tryt 60 "linked Allclean in the user's folder" ./Allclean; echo "   user files lost: $(find . -type f | sort | comm -23 ../u0 - | tr '\n' ' ')"; echo "   case: $(cd $C; ls -d [0-9]* solid 2>/dev/null | tr '\n' ' ')"
rm Allclean; ln -s $C/Allrun Allrun; tryt 60 "linked Allrun -noRun in the user's folder" ./Allrun $PREV -noRun; echo "   user files lost: $(find . -type f | sort | comm -23 ../u0 - | tr '\n' ' ') | new here: $(find . -newer ../u0 -type f | tr '\n' ' ' | cut -c1-200)"
rm Allrun; tryt 60 "bash <case>/Allclean from the user's folder" bash $C/Allclean; echo "   user files lost: $(find . -type f | sort | comm -23 ../u0 - | tr '\n' ' ')"

#!/bin/bash
# CASETIMEOUT=600
# m03 (fix19g's allrunNotALink, adv50a k06 (e), varied beyond the hard-linked Allclean): the finished preview bd ($C, its
# tutorial Allclean and Allrun copied in) and a user's folder $W/user (0/U, constant/polyMesh/points, postProcessing/notes.txt,
# log.mine, VTK/x.vtk, 1e-09/p): (a) a HARD link of the case's Allrun in the user's folder, `./Allrun -noRun`;
# (b) the user's folder holding a system/ (a case of the user's: system/controlDict) and a hard link of $C/Allclean
# (refused: the link) and a plain copy (documented: cleans that case); (c) `. $C/Allclean` and `source $C/Allclean`
# sourced from the user's folder by a bash script ($0 = bash: the script's name is not Allclean); (d) `bash -c
# "$C/Allclean"` and `sh $C/Allclean` (dash) from the user's folder; (e) a second hard link of Allclean inside the case
# itself (Allclean.bak): the case's own ./Allclean (refused, harmless; the message); (f) a case copied with `cp -al`
# (every file a hard link: the copy's ./Allclean and the original's); (g) Allclean through /proc/self/fd (bash
# /dev/fd/N < Allclean). Never a user's file lost; a case cleaned only by its own Allclean.
. "$(dirname "$0")/../lib.sh"
mkuser() { rm -rf $W/user; mkdir -p $W/user/0 $W/user/constant/polyMesh $W/user/postProcessing $W/user/VTK $W/user/1e-09
  for f in 0/U constant/polyMesh/points postProcessing/notes.txt log.mine VTK/x.vtk 1e-09/p; do echo "user's $f" > $W/user/$f; done; (cd $W/user; find . -type f | sort > $W/u0); }
lost() { echo "   user files lost: $(cd $W/user; find . -type f | sort | comm -23 $W/u0 - | tr '\n' ' ')| user new: $(cd $W/user; find . -type f | sort | comm -13 $W/u0 - | tr '\n' ' ' | cut -c1-200)| case: $(cd $C; ls -d [0-9]* solid constant/cell.msh 2>/dev/null | tr '\n' ' ')"; }
fresh() { cd $W; rm -rf blast user; bd; cp "$ROOT/tutorials/blast/axisymmetricPreview/Allclean" "$ROOT/tutorials/blast/axisymmetricPreview/Allrun" .; C=$PWD; mkuser; cd $W/user; }
fresh; ln $C/Allrun Allrun; tryt 60 "(a) user/Allrun a hard link of the case's, ./Allrun -noRun" ./Allrun -noRun; lost; rm -f Allrun
fresh; mkdir -p system; echo "user's controlDict" > system/controlDict; (cd $W/user; find . -type f | sort > $W/u0); ln $C/Allclean Allclean; tryt 60 "(b1) user's folder with system/, a hard link of Allclean" ./Allclean; lost; rm -f Allclean
cp $C/Allclean Allclean; tryt 60 "(b2) user's folder with system/, a copy of Allclean (documented: cleans it)" ./Allclean; lost; rm -f Allclean
fresh; printf '#!/bin/bash\n. %s/Allclean\necho sourced rc $?\n' $C > $W/src.sh; tryt 60 "(c1) a script sourcing \$C/Allclean from the user's folder" bash $W/src.sh; lost; echo "   out: $(tail -3 $W/try.log | tr '\n' ' ' | cut -c1-300)"
fresh; tryt 60 "(c2) bash -c 'source \$C/Allclean' in the user's folder" bash -c "source $C/Allclean"; lost; echo "   out: $(tail -3 $W/try.log | tr '\n' ' ' | cut -c1-300)"
fresh; tryt 60 "(d1) bash -c \$C/Allclean from the user's folder" bash -c "$C/Allclean"; lost
fresh; tryt 60 "(d2) sh \$C/Allclean (dash) from the user's folder" sh $C/Allclean; lost
fresh; cd $C; ln Allclean Allclean.bak; tryt 60 "(e) the case's own ./Allclean with a hard link Allclean.bak beside it" ./Allclean; lost; cd $W/user
fresh; cd $W; cp -al blast copy; cd copy; tryt 60 "(f1) ./Allclean in a cp -al copy of the case" ./Allclean; echo "   copy: $(ls -d [0-9]* solid 2>/dev/null | tr '\n' ' ') | original: $(cd $C; ls -d [0-9]* solid 2>/dev/null | tr '\n' ' ')"
tryt 60 "(f2) ./Allrun -noRun in the cp -al copy" ./Allrun -noRun; echo "   original's files changed through the links: $(cd $C; find . -newer $W/u0 -type f | head -5 | tr '\n' ' ')"; cd $W; rm -rf copy
fresh; tryt 60 "(g) bash /dev/fd/3 3< \$C/Allclean from the user's folder" bash -c "bash /dev/fd/3 3< $C/Allclean"; lost
fresh; cd $C; tryt 60 "(h) the case's own ./Allclean (control)" ./Allclean; lost

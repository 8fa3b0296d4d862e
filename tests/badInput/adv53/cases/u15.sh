#!/bin/bash
# CASETIMEOUT=300
# u15 (fix19i row "an Allrun or Allclean whose text a shell runs" with the lead's correction "a file named Allrun* or
# Allclean*, e.g. Allrun.pre", varied: a copy of a tutorial's Allclean under another name of that form, kept as a backup
# in a user's folder that is no case): a user's folder holding 0/U, 1e-09/p, log.mine, postProcessing/notes.txt, VTK/v.vtk
# and (a) Allclean.bak (the preview's Allclean copied), run there as `bash Allclean.bak`; (b) Allclean~ (an editor's
# backup) run as `./Allclean~`; (c) control: the copy named Allclean (refused: "no system/ folder: it is not a case").
# Expected: each refused as (c) is, the user's files kept; removed = DATALOSS.
. "$(dirname "$0")/../lib.sh"
mk() { rm -rf $W/u; mkdir -p $W/u; cd $W/u; for f in 0/U 1e-09/p log.mine postProcessing/notes.txt VTK/v.vtk; do mark $f; done; cp $ROOT/tutorials/blast/axisymmetricPreview/Allclean "$1"; chmod +x "$1"; }
chk() { for f in 0/U 1e-09/p log.mine postProcessing/notes.txt VTK/v.vtk; do kept_ $f; done; }
mk Allclean.bak; tryt 60 "(a) bash Allclean.bak in a user's folder (no system/)" bash Allclean.bak; echo "   said: $(tail -2 $W/try.log | tr '\n' '|' | cut -c1-250)"; chk
mk 'Allclean~'; tryt 60 "(b) ./Allclean~ in a user's folder (no system/)" './Allclean~'; echo "   said: $(tail -2 $W/try.log | tr '\n' '|' | cut -c1-250)"; chk
mk Allclean; tryt 60 "(c) control: bash Allclean in a user's folder (no system/)" bash Allclean; echo "   said: $(tail -2 $W/try.log | tr '\n' '|' | cut -c1-250)"; chk

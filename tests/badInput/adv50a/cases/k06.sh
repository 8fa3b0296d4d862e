#!/bin/bash
# CASETIMEOUT=900
# k06 (adv49b i30 / fix19f's allrunNotALink varied: Allrun/Allclean through links, `..` components, a linked folder, a
# hard link, a path with a space; bind mounts need root: not run): the finished preview bd with its Allclean ($C) and a
# user's folder $W/user (0/U, constant/polyMesh/points, postProcessing/notes.txt, log.mine, VTK/x.vtk, 1e-09/p):
# (a) `$W/lnk/Allclean` where $W/lnk -> $C (a linked folder: the case itself; cleans the case), (b) from $W/user:
# `../blast/./Allclean` and `bash ../user/../blast/Allclean` (cleans the case), (c) user/Allclean -> a link to a link to
# $C/Allclean (refused), (d) `bash Allclean` and through PATH (`Allclean` found in PATH=$W/user) with user/Allclean a link
# (refused), (e) user/Allclean a HARD link of $C/Allclean (a copy by another name: the documented limit), (f) a case at
# "$W/a b/blast" (a space) beside a user's folder $W/a: its Allclean leaves $W/a alone, (g) a solver running in $C (a
# restart to 3e-9) and `$W/lnk/Allclean` 3 s later (the lock seen through the linked path: refused naming the solver),
# (h) the solver started in $W/lnk and `$C/Allclean` by the real path (refused), (i) the case's own Allclean a link to
# the tutorial's (a case made by linking scripts: refused or cleans the case, nothing else). Never a user's file lost,
# never the case cleaned while a solver runs in it.
. "$(dirname "$0")/../lib.sh"
mkuser() { rm -rf $W/user; mkdir -p $W/user/0 $W/user/constant/polyMesh $W/user/postProcessing $W/user/VTK $W/user/1e-09
  for f in 0/U constant/polyMesh/points postProcessing/notes.txt log.mine VTK/x.vtk 1e-09/p; do echo "user's $f" > $W/user/$f; done; (cd $W/user; find . -type f | sort > $W/u0); }
lost() { echo "   user files lost: $(cd $W/user; find . -type f | sort | comm -23 $W/u0 - | tr '\n' ' ')| case: $(cd $C; ls -d [0-9]* solid constant/cell.msh 2>/dev/null | tr '\n' ' ')"; }
fresh() { cd $W; rm -rf blast lnk; bd; cp "$ROOT/tutorials/blast/axisymmetricPreview/Allclean" .; C=$PWD; ln -s $C $W/lnk; mkuser; cd $W/user; }
fresh; tryt 60 "(a) \$W/lnk/Allclean (lnk -> the case)" $W/lnk/Allclean; lost
fresh; tryt 60 "(b1) ../blast/./Allclean from the user's folder" ../blast/./Allclean; lost
fresh; tryt 60 "(b2) bash ../user/../blast/Allclean from the user's folder" bash ../user/../blast/Allclean; lost
fresh; ln -s $C/Allclean $W/lnk2; ln -s $W/lnk2 Allclean; tryt 60 "(c) user/Allclean -> lnk2 -> case/Allclean" ./Allclean; lost; rm -f Allclean $W/lnk2
fresh; ln -s $C/Allclean Allclean; tryt 60 "(d1) bash Allclean (a link) in the user's folder" bash Allclean; lost
tryt 60 "(d2) Allclean through PATH=\$W/user (a link)" env PATH=$W/user:$PATH Allclean; lost
cd /; tryt 60 "(d3) \$W/user/Allclean (a link) from /" $W/user/Allclean; lost; cd $W/user; rm -f Allclean
fresh; ln $C/Allclean Allclean; tryt 60 "(e) user/Allclean a hard link of the case's" ./Allclean; lost; rm -f Allclean
cd $W; rm -rf "a b" a; mkdir -p "a b" a/keep; echo mine > a/keep/file; echo mine > a/file0; bd; cp "$ROOT/tutorials/blast/axisymmetricPreview/Allclean" .; cd $W; mv blast "a b/blast"
tryt 60 "(f) \"\$W/a b/blast/Allclean\"" "$W/a b/blast/Allclean"; echo "   \$W/a: $(cd $W/a; find . -type f | sort | tr '\n' ' ')| case: $(cd "$W/a b/blast"; ls -d [0-9]* solid 2>/dev/null | tr '\n' ' ')"
fresh; cd $C; rs; rm -f .runLock; (cellBlastFoam > log.bg 2>&1; echo "bg rc $?" >> log.bg) & bp=$!; sleep 3; cd $W/user
tryt 60 "(g) \$W/lnk/Allclean while cellBlastFoam runs in the case" $W/lnk/Allclean; lost; echo "   lock: $(head -c 300 $C/.runLock 2>/dev/null | tr '\n' ' ')"; wait $bp; echo "   solver: $(tail -1 $C/log.bg) | times: $(cd $C; ls -d [0-9]* | tr '\n' ' ')"
fresh; cd $W/lnk; rs; rm -f .runLock; (cellBlastFoam > log.bg 2>&1; echo "bg rc $?" >> log.bg) & bp=$!; sleep 3; cd $W/user
tryt 60 "(h) \$C/Allclean (real path) while cellBlastFoam runs in \$W/lnk" $C/Allclean; lost; wait $bp; echo "   solver: $(tail -1 $C/log.bg) | times: $(cd $C; ls -d [0-9]* | tr '\n' ' ')"
fresh; cd $C; rm -f Allclean; ln -s "$ROOT/tutorials/blast/axisymmetricPreview/Allclean" Allclean; tryt 60 "(i) the case's Allclean a link to the tutorial's, ./Allclean in the case" ./Allclean; lost; echo "   tutorial: $(cd $ROOT/tutorials/blast/axisymmetricPreview; git status --short . | head -3 | tr '\n' ' ')"

#!/bin/bash
# CASETIMEOUT=600
# o01 (fix19h's sourced Allrun/Allclean, adv51 m03, varied: the script's text run by a shell that reads it from stdin or
# from a string, not sourced and not run by path; and sourced by dash): a user's folder $W/u that looks like a case
# (system/controlDict, 0/U, 1e-09/p, VTK/x.vtk, constant/polyMesh/points, log.mine, postProcessing/notes.txt); in it:
# (a) `bash < $C/Allclean` (C: a copy of tutorials/verification/waterPulseWall), (b) `cat $C/Allclean | bash`,
# (c) `bash -c "$(cat $C/Allclean)"`, (d) `sh -c ". $C/Allclean"` (dash: no BASH_SOURCE), (e) a user's bash script doing
# `eval "$(cat $C/Allclean)"`, (f) the blast preview's Allclean by `bash < `, (g) the indentation Allrun by `bash < `
# (a mesh and a run in the user's folder?). Each: refused (the script cannot find its case), nothing of the user's removed
# or written; the user's files removed = DATALOSS.
. "$(dirname "$0")/../lib.sh"
T=$ROOT/tutorials
mk() { rm -rf $W/u; mkdir -p $W/u/system $W/u/0 $W/u/1e-09 $W/u/VTK $W/u/constant/polyMesh $W/u/postProcessing; cd $W/u
  for f in system/controlDict 0/U 1e-09/p VTK/x.vtk constant/polyMesh/points log.mine postProcessing/notes.txt; do mark $f; done; same0; }
chk() { echo "   user's folder: $(for f in system/controlDict 0/U 1e-09/p VTK/x.vtk constant/polyMesh/points log.mine postProcessing/notes.txt; do [ "$(cat $f 2>/dev/null)" = "users data $f" ] || echo -n "$f LOST "; done) | new: $(cd $W/u; find . -newer $W/same0 -type f | grep -v '^\./\(system/controlDict\|0/U\|1e-09/p\|VTK/x.vtk\|constant/polyMesh/points\|log.mine\|postProcessing/notes.txt\)$' | tr '\n' ' ' | cut -c1-300)"; same1; }
cp -r $T/verification/waterPulseWall $W/wpw; cp -r $T/blast/axisymmetricPreview $W/prev; cp -r $T/indentation/averageCell $W/ind0; C=$W/wpw
mk; tryt 60 "(a) bash < \$C/Allclean in the user's folder" bash < $C/Allclean; tail -2 $W/try.log | sed 's/^/   out: /'; chk
mk; tryt 60 "(b) cat \$C/Allclean | bash" bash -c "cat $C/Allclean | bash"; tail -2 $W/try.log | sed 's/^/   out: /'; chk
mk; tryt 60 "(c) bash -c \"\$(cat \$C/Allclean)\"" bash -c "$(cat $C/Allclean)"; tail -2 $W/try.log | sed 's/^/   out: /'; chk
mk; tryt 60 "(d) sh (dash) -c '. \$C/Allclean'" sh -c ". $C/Allclean"; tail -2 $W/try.log | sed 's/^/   out: /'; chk
mk; printf '#!/bin/bash\n# a user script that runs the tutorial clean-up text\neval "$(cat %s/Allclean)"\necho user script went on\n' $C > $W/user.sh
tryt 60 "(e) a user's script: eval \"\$(cat \$C/Allclean)\"" bash $W/user.sh; tail -2 $W/try.log | sed 's/^/   out: /'; chk
mk; tryt 60 "(f) bash < the blast preview's Allclean" bash < $W/prev/Allclean; tail -2 $W/try.log | sed 's/^/   out: /'; chk
mk; rm -rf system; mark system/controlDict; same0; tryt 120 "(g) bash < the indentation Allrun" bash < $W/ind0/Allrun; tail -3 $W/try.log | sed 's/^/   out: /'; chk

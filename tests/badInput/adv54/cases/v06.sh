#!/bin/bash
# CASETIMEOUT=600
# v06 (fix19j row "SIGXFSZ" varied, class 6: `ulimit -f` under the tools fix19j's SIGXFSZ row did not name - it ran cellBlastFoam,
# cellIndentationFoam, solidToFoam): (a) cellMesh in a copy of the preview without its cell.msh, ulimit -f 8 (KiB; the
# cell.msh is ~60 KiB), then what constant/cell.msh holds and cellMesh again without the limit; (b) setRiemannProblem in
# the sod tube (0/ fields ~ 10 KiB) under ulimit -f 4, then rhoRiemannFoam; (c) planeWave on bd under ulimit -f 8
# (Python ignores SIGXFSZ: the write fails), then incidentWindow.py on what it left; (d) plotIndentation.py under
# ulimit -f 4 on idn (indentation.png). Expected: each fails rc != 0 naming the file it could not write ("File too
# large"/file size limit), no signal, no traceback, and leaves no cut file that a later run takes for whole.
. "$(dirname "$0")/../lib.sh"
lim() { local l=$1; shift; tryt 300 "ulimit -f $l: $*" bash -c "ulimit -f $l; exec \"\$@\"" _ "$@"; echo "   sig $(sig) | said: $(say 3 | cut -c1-300)"; }
bd; ls -la constant/cell.msh | awk '{print "   cell.msh " $5 " B"}'; mv constant/cell.msh $W/cell.msh0; lim 8 cellMesh; echo "   cell.msh now: $(stat -c %s constant/cell.msh 2>/dev/null || echo none) B"
tryt 300 "(a2) cellMesh again, no limit" cellMesh; echo "   said: $(say 2 | cut -c1-250) | cell.msh $(cmp -s constant/cell.msh $W/cell.msh0 && echo 'as before' || echo differs)"
mv $W/cell.msh0 constant/cell.msh.orig; head -c 9000 constant/cell.msh.orig > constant/cell.msh; rs; rm -f .runLock; tryt 300 "(a3) the restart on a cell.msh cut at 9000 B (as a cut write would leave it)" cellBlastFoam; echo "   said: $(say 2 | cut -c1-250)"
cd $W; sod; rm -rf 0; cp -r 0.orig 0; lim 4 setRiemannProblem; echo "   0/: $(ls -la 0 | awk 'NR>1{print $NF ":" $5}' | tr '\n' ' ')"
tryt 300 "(b2) rhoRiemannFoam after it" rhoRiemannFoam; echo "   said: $(say 2 | cut -c1-250)"
cd $W; bd; lim 8 planeWave -case .; echo "   postProcessing/planeWave/0: $(ls -la postProcessing/planeWave/0 2>/dev/null | awk 'NR>3{print $NF ":" $5}' | tr '\n' ' ')"
iw .; echo "   (c2) incidentWindow after: $(grep -a -v '^ *$' $W/try.log | tail -n 2 | tr '\n' '|' | cut -c1-300)"
cd $W; idn; lim 4 /usr/bin/python3 $ROOT/tutorials/indentation/plotIndentation.py .; echo "   indentation.png $(stat -c %s indentation.png 2>/dev/null || echo none) B, results.md $(stat -c %s results.md 2>/dev/null || echo none) B"

#!/bin/bash
# CASETIMEOUT=600
# u08 (fix19i row "an Allrun or Allclean whose text a shell runs, or whose case's folders are links" (allrunNotALink),
# varied: run by another shell, and the folders it does not list): (a) `sh Allclean` (dash, /bin/sh) in the finished
# preview (bd plus the tutorial's Allclean), (b) `sh Allrun -noRun` there; then B, a copy of A (bd) without results whose
# (c) postProcessing/, (d) solid/ and 1e-09/, (e) VTK/ are links to A's: B's ./Allclean; (f) B (postProcessing a link
# to A's, A finished) run by cellBlastFoam: does it write into A's logs? Expected: (a), (b) run as bash would or refused
# naming the shell to use, nothing half-done; (c)-(e) A's files kept; (f) refused naming the link (or A's logs kept); A's
# files changed = DATALOSS; a shell's syntax error as the only word = UNCLEAR (low).
. "$(dirname "$0")/../lib.sh"
bd; cp $ROOT/tutorials/blast/axisymmetricPreview/Allclean .; rm -f .runLock; sums > $W/s0
tryt 60 "(a) sh Allclean (dash)" sh Allclean; echo "   said: $(tail -2 $W/try.log | tr '\n' '|' | cut -c1-250) | changed: $(changed $W/s0 | cut -c1-200)"
tryt 60 "(b) sh Allrun -noRun (dash)" sh Allrun -noRun -noPlots -noVTK; echo "   said: $(tail -2 $W/try.log | tr '\n' '|' | cut -c1-250) | changed: $(changed $W/s0 | cut -c1-200)"
cd $W; mv blast A; mkdir -p A/VTK; mark A/VTK/mine.vtk; cd A; sums > $W/sA; cd $W
mkB() { rm -rf $W/B; cp -a $W/A $W/B; cd $W/B; rm -rf postProcessing solid [1-9]* VTK; for l in "$@"; do ln -s $W/A/$l $l; done; }
mkB postProcessing; tryt 60 "(c) B's ./Allclean, B/postProcessing -> A's" ./Allclean; echo "   said: $(tail -1 $W/try.log | cut -c1-200) | A changed: $(cd $W/A; changed $W/sA | cut -c1-200)"
mkB solid 1e-09; tryt 60 "(d) B's ./Allclean, B/solid and B/1e-09 -> A's" ./Allclean; echo "   said: $(tail -1 $W/try.log | cut -c1-200) | A changed: $(cd $W/A; changed $W/sA | cut -c1-200)"
mkB VTK; tryt 60 "(e) B's ./Allclean, B/VTK -> A's" ./Allclean; echo "   said: $(tail -1 $W/try.log | cut -c1-200) | A changed: $(cd $W/A; changed $W/sA | cut -c1-200)"
mkB postProcessing; sed -i 's/^startFrom .*/startFrom startTime;/' system/controlDict
tryt 300 "(f) B (postProcessing -> A's, A finished) run by cellBlastFoam from 0" cellBlastFoam; echo "   End $(grep -a -c '^End' $W/try.log) | said: $(say 3 | cut -c1-300) | A changed: $(cd $W/A; changed $W/sA | cut -c1-250)"

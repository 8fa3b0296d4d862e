#!/bin/bash
# CASETIMEOUT=600
# l19 (new, class 6/5: a full disk while the meshes are written - cellMesh's gmsh .msh files, the Allrun's later steps -
# and what the next step makes of a cut mesh): the quarter's mesh folder (qm) in a tmpfs with 40 KB free beyond its
# inputs: (a) cellMesh: rc, message, what constant/ holds (cell.msh whole, cut or absent); (b) the folder copied out of
# the tmpfs, then cellMesh again with room: it writes whole meshes (a cut file left by (a) is not taken as done); (c) the
# preview prepared by its Allrun -noRun in a tmpfs with 300 KB free, then its Allrun again with room. Expected: (a) rc
# != 0 naming the file and the full disk, no cut mesh left under the final name; (b), (c) the later run whole; a cut
# .msh read as a mesh by a later step = SILENT/DATALOSS; a signal = CRASH.
. "$(dirname "$0")/../lib.sh"
fs() { mkdir -p $W/fs; umount -l $W/fs 2>/dev/null; mount -t tmpfs -o size=$1k tmpfs $W/fs; }
qm; sz=$(du -sk $W/m | cut -f1); fs $((sz + 40)); cp -a $W/m $W/fs/m; cd $W/fs/m; echo "   free: $(df -k --output=avail $W/fs | tail -1) KB"
cm; echo "   constant/: $(ls -la constant | awk 'NR>1 {print $5, $9}' | tr '\n' ' ' | cut -c1-250)"
cd $W; rm -rf m2; cp -a fs/m m2; umount -l $W/fs; cd m2; cm; echo "   (b) again with room: constant/: $(ls -la constant | awk 'NR>1 {print $5, $9}' | tr '\n' ' ' | cut -c1-250)"
cd $W; prev; cd $W; sz=$(du -sk $W/c | cut -f1); fs $((sz + 300)); cp -a $W/c $W/fs/c; cd $W/fs/c
tryt 400 "(c) the preview's Allrun -noRun with 300 KB free" ./Allrun -h 0.5e-6 -far 4e-6 -dz 0.5e-6 -cell 1e-6 -Z 20e-6 -endTime 2e-9 -noPlots -noVTK -noRun; echo "   sig $(sig) | said: $(grep -a -i -m3 'error\|space\|failed' $W/try.log | tr '\n' '|' | cut -c1-300) | constant/: $(ls constant | tr '\n' ' ' | cut -c1-150)"
cd $W; rm -rf c2; cp -a fs/c c2; umount -l $W/fs; cd c2; rm -f .runLock .allrunLock*
tryt 400 "(c2) the Allrun again with room" ./Allrun -h 0.5e-6 -far 4e-6 -dz 0.5e-6 -cell 1e-6 -Z 20e-6 -endTime 2e-9 -noPlots -noVTK -noRun; echo "   said: $(grep -a -i -m3 'error\|refus' $W/try.log | tr '\n' '|' | cut -c1-300)"
tryt 300 "(c3) cellBlastFoam on it" cellBlastFoam; echo "   End $(grep -a -c '^End' $W/try.log) | said: $(say 2 | cut -c1-250)"

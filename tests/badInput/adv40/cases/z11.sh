#!/bin/bash
# z11: blast finished; the user's own files put beside the results: postProcessing/fsi/0/notes.txt, postProcessing/solidProbes/0/plot.png, solid/view.pvsm, postProcessing/myPlots/a.png; then cellBlastFoam -overwrite (a whole new run): are the user's files kept (or the run refused naming them)?
. "$(dirname "$0")/../lib.sh"
blastDone; echo "my notes" > postProcessing/fsi/0/notes.txt; head -c 3000 /dev/urandom > postProcessing/solidProbes/0/plot.png; echo "<ParaView/>" > solid/view.pvsm; mkdir -p postProcessing/myPlots; echo png > postProcessing/myPlots/a.png
snap ../before; try "-overwrite" cellBlastFoam -overwrite
for f in postProcessing/fsi/0/notes.txt postProcessing/solidProbes/0/plot.png solid/view.pvsm postProcessing/myPlots/a.png; do k=$(grep " ./$f$" ../before | awk '{print $1}'); w=$(find . -type f -print0 | xargs -0 md5sum | grep "^$k" | awk '{print $2}' | tr '\n' ' '); echo "   $f: ${w:-GONE}"; done
ls -a postProcessing postProcessing/fsi solid | tr '\n' ' '; echo

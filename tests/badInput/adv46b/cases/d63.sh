#!/bin/bash
# d63 (class 4, a case path holding a literal "$HOME" and "~" folder: $W/\$HOME/ind and $W/~/ind run with -case and from inside): runs in that folder (results there, nothing written under the real $HOME) or refused naming the path; SILENT if OpenFOAM expands $HOME and runs another case.
. "$(dirname "$0")/../lib.sh"
ind; cd $W; mkdir -p "\$HOME" "~"; cp -a ind "\$HOME/ind"; cp -a ind "~/ind"; ls -a $HOME > ../home0
tryt 120 "(a) -case \$W/\$HOME/ind" cellIndentationFoam -case "$W/\$HOME/ind"; echo "   results in \$W/\$HOME/ind: $(ls "$W/\$HOME/ind/postProcessing/indentation" 2>&1 | tr "\n" " ")"
cd "$W/~/ind"; tryt 120 "(b) in \$W/~/ind" cellIndentationFoam; echo "   results here: $(ls postProcessing/indentation 2>&1 | tr "\n" " ")"; ls -a $HOME | diff ../../../home0 - && echo "   HOME unchanged"

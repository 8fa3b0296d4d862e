#!/bin/bash
# f07 (class 1, the whole case moved: bd renamed to another folder name and reached through a symbolic link too), restart to 3e-9 in the moved case: continues (a case's location is no input), rc 0; a second restart to 4e-9 through a symbolic link to it continues too. Refusing is UNCLEAR low.
. "$(dirname "$0")/../lib.sh"
bd; rs; cd $W; mv blast moved; cd moved
tryt 240 "(a) moved case" cellBlastFoam; cont; after
ln -s $W/moved $W/link; cd $W/link; blastEnd 4e-9 1e-9; tryt 240 "(b) through a link" cellBlastFoam; cont; after

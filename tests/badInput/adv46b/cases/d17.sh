#!/bin/bash
# d17 (class 1+3, must be ACCEPTED: the restart of the finished preview run through a symbolic link to the case, -case $W/lnk): continues as through its real path.
. "$(dirname "$0")/../lib.sh"
bd; rs; ln -s $W/blast $W/lnk; cd $W
tryt 240 "restart through a link" cellBlastFoam -case $W/lnk; cont; cd blast; after; ls -a $W

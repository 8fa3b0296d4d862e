#!/bin/bash
# d33 (class 3, .runLock a symbolic link to a user file): cellBlastFoam, solidToFoam and planeWave -inflow ... never write through it (the user file unchanged), refuse naming the link.
. "$(dirname "$0")/../lib.sh"
bd; echo precious > $W/victim; ln -s $W/victim .runLock
tryt 60 "cellBlastFoam, lock a link" cellBlastFoam; echo "   victim: $(cat $W/victim)"; tryt 60 "solidToFoam, lock a link" solidToFoam solid/solid.h5; echo "   victim: $(cat $W/victim)"; tryt 60 "planeWave, lock a link" planeWave -inflow 10e-6 -Z 20e-6; echo "   victim: $(cat $W/victim); link: $(readlink .runLock)"

#!/bin/bash
# w26: blast: solid/solid.h5 is a symlink to ANOTHER finished case's solid.h5 (a user sharing files), restart to 3 ns: is the other case's file written through the link?
. "$(dirname "$0")/../lib.sh"
blastDone; latest; cd ..; cp -r blast other; md5sum other/solid/solid.h5 > o.md5; cd blast; rm solid/solid.h5; ln -s ../../other/solid/solid.h5 solid/solid.h5; blastEnd 3e-9 1e-9
run 120 cellBlastFoam > log.r 2>&1; fatal log.r 4; tail -1 log.r; (cd .. && md5sum -c o.md5) && echo "other case's solid.h5 unchanged"; ls -la solid | tail -2

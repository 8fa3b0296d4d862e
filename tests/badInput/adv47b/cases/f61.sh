#!/bin/bash
# f61 (environment, few file descriptors): the preview's restart to 3e-9 and the killed indentation's restart under ulimit -n 24 / 12: each ends with an error naming the file it could not open (rc != 0, no signal) or runs to its end with its results whole; never a signal, never a time committed with a file missing.
. "$(dirname "$0")/../lib.sh"
bd; rs; ( ulimit -n 24; tryt 200 "(a) blast, ulimit -n 24" cellBlastFoam ); grep -a -c 'Segmentation\|sigFpe\|terminate\|signal' $W/try.log; after; ls 3e-09 2>/dev/null | tr '\n' ' '; echo
ik; ( ulimit -n 12; tryt 200 "(b) indentation, ulimit -n 12" cellIndentationFoam ); grep -a -c 'Segmentation\|sigFpe\|terminate\|signal' $W/try.log; after

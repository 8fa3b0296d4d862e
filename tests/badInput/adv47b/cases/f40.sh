#!/bin/bash
# f40 (environment, a read-only case): the finished preview made read-only (bind mount), restart to 3e-9: an error naming the case and that it cannot be written (rc != 0, no signal), nothing changed; then the killed indentation read-only: the same.
. "$(dirname "$0")/../lib.sh"
bd; rs; ro $W/blast; tryt 120 "(a) blast read-only" cellBlastFoam; grep -a -c 'Segmentation\|sigFpe\|terminate' $W/try.log
ik; ro $W/ind; tryt 120 "(b) indentation read-only" cellIndentationFoam; grep -a -c 'Segmentation\|sigFpe\|terminate' $W/try.log

#!/bin/bash
# w89: ind killed after a checkpoint; only a comment of indenterProperties and of solidProperties changed (a note added): the restart accepted, not refused?
. "$(dirname "$0")/../lib.sh"
indKilled 0.5; echo "// a user's note: looks fine" >> constant/indenterProperties; sed -i '1a // note' constant/solidProperties
run 200 cellIndentationFoam > log.r 2>&1; fatal log.r 4; tail -1 log.r

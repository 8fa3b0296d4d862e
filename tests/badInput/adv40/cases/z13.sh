#!/bin/bash
# z13: a case copied with its STALE lock: an indentation (10x finer steps) SIGKILLed after its first checkpoint (lock left), the case copied with cp -a (the lock names the original folder and a dead process); restart in the copy and in the original: each taken over (stale) or refused with a message that says what to do?
. "$(dirname "$0")/../lib.sh"
indKilled 0.3; echo "lock: $(lockOf)"; cp -a $W/ind $W/copy
cd $W/copy; tryf "copy: restart" cellIndentationFoam; echo "   copy's lock after: $(lockOf)"
cd $W/ind; tryf "original: restart" cellIndentationFoam; echo "   original's lock after: $(lockOf)"

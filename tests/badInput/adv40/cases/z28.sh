#!/bin/bash
# z28: odd .runLock shapes never tried: (a) a DANGLING symbolic link (to a file that does not exist: O_EXCL fails on it), (b) a link to /dev/null, (c) a lock file with mode 000 owned by another user (nobody): cellIndentationFoam in a fresh smoke case: refused saying what the lock is (and what to do), never run beside it or crash?
. "$(dirname "$0")/../lib.sh"
ind; ln -s $W/nowhere/lock .runLock; try "(a) dangling link" cellIndentationFoam; echo "   lock now: $(ls -l .runLock 2>&1 | cut -c1-120); results: $(ls postProcessing/indentation 2>/dev/null | tr '\n' ' ')"; rm -rf .runLock postProcessing
ln -s /dev/null .runLock; try "(b) link to /dev/null" cellIndentationFoam; echo "   results: $(ls postProcessing/indentation 2>/dev/null | tr '\n' ' ')"; rm -rf .runLock postProcessing
printf 'pid 999999\nhost %s\n' "$(hostname)" > .runLock; chmod 000 .runLock; chown nobody .runLock 2>/dev/null
try "(c) mode-000 lock of another user (as $(id -un))" cellIndentationFoam; echo "   results: $(ls postProcessing/indentation 2>/dev/null | tr '\n' ' ')"

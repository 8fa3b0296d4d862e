#!/bin/bash
# CASETIMEOUT=900
# l26 (new, class 2/1: a run stopped by Ctrl-C or by a batch system's SIGTERM - earlier passes killed with SIGKILL):
# bd restarted to 8e-9 (writes every 1e-9) and (a) SIGINT, (b) SIGTERM, (c) SIGHUP sent 2, 4 and 6 s after its start
# (three runs each; first run with 2, 4, 6 s: the run had ended before most signals on this machine, re-run with 0.4, 0.9, 1.4 s); then `startFrom latestTime` to 8e-9 again. Expected: each stop leaves the case restartable (no
# uncommitted time taken), the lock released or taken over, and the final 8e-09/p and the four logs bitwise those of an
# uninterrupted run; a difference = SILENT; the case not restartable = DATALOSS. (The solver is started with SIGINT's
# default action restored: a background job of a script ignores SIGINT, as the first run showed - rc 0 after SIGINT.)
. "$(dirname "$0")/../lib.sh"
bd; latest; blastEnd 8e-9 1e-9; rm -f .runLock; cd $W; cp -a blast b0; cp -a blast ref; cd ref; tryt 600 "(0) uninterrupted to 8e-9" cellBlastFoam
for s in INT TERM HUP; do for d in 0.4 0.9 1.4; do cd $W; rm -rf blast; cp -a b0 blast; cd blast
  /usr/bin/python3 -c "import os, signal; signal.signal(signal.SIGINT, signal.SIG_DFL); os.execvp('cellBlastFoam', ['cellBlastFoam'])" > log.a 2>&1 & p=$!; sleep $d; kill -$s $p; wait $p; r=$?
  tryt 600 "($s at $d s, rc $r) then the restart to 8e-9" cellBlastFoam; echo "   End $(grep -a -c '^End' $W/try.log) | said: $(say 2 | cut -c1-200) | aside: $(ls -d *.incomplete* .*overwritten* 2>/dev/null | tr '\n' ' ') | 8e-09/p: $(cmp -s 8e-09/p $W/ref/8e-09/p && echo same || echo DIFFERS) | logs: $(sameSeries $W/ref | awk '{print $2}' | tr '\n' ' ') | solid.h5 $(h5same solid/solid.h5 $W/ref/solid/solid.h5)"; done; done

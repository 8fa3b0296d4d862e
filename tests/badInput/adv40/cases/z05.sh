#!/bin/bash
# z05: power loss shapes with NUL bytes in an indentation killed after its first checkpoint, restart: (a) restart.h5 all NUL (same size); (b) force.dat's last 200 bytes NUL; (c) solid.h5 all NUL; (d) peaks.dat all NUL. Each refused naming the file, or continued to an undamaged end (no NUL, times increasing)?
. "$(dirname "$0")/../lib.sh"
indKilled 0.3; cp -r . ../keep; P=postProcessing/indentation
fresh() { cd $W; rm -rf $W/ind; cp -r $W/keep $W/ind; cd $W/ind; }
chk() { echo "   $(forceOk $P/force.dat); $(forceOk $P/peaks.dat)"; }
nul $P/restart.h5; tryf "(a) restart.h5 NUL" cellIndentationFoam; chk
fresh; /usr/bin/python3 -c "
b=bytearray(open('$P/force.dat','rb').read()); b[-200:]=b'\0'*200; open('$P/force.dat','wb').write(b)"; tryf "(b) force.dat tail NUL" cellIndentationFoam; chk
fresh; nul $P/solid.h5; tryf "(c) solid.h5 NUL" cellIndentationFoam; chk
fresh; nul $P/peaks.dat; tryf "(d) peaks.dat NUL" cellIndentationFoam; chk

#!/bin/bash
# z04: power loss shapes with NUL bytes (a file whose size reached the disk, its data not: ext4/XFS delayed allocation) in a blast run to 2 ns, restart to 3 ns: (a) 2e-09/.writeCommitted all NUL; (b) marker whole, 2e-09/p all NUL; (c) both; (d) marker whole, 2e-09/uniform/time all NUL; (e) marker whole, postProcessing/fsi/0/coupling.dat's last 300 bytes NUL. Each: moved aside / refused naming the file, never continued from it?
. "$(dirname "$0")/../lib.sh"
blastDone; latest; blastEnd 3e-9 1e-9; cp -r . ../keep
fresh() { cd $W; rm -rf $W/blast; cp -r $W/keep $W/blast; cd $W/blast; }
nul 2e-09/.writeCommitted; tryf "(a) marker NUL" cellBlastFoam; echo "   dirs: $(ls -da [1-9]* 2>/dev/null | tr '\n' ' ')"
fresh; nul 2e-09/p; tryf "(b) p NUL" cellBlastFoam; echo "   dirs: $(ls -da [1-9]* 2>/dev/null | tr '\n' ' ')"
fresh; nul 2e-09/p 2e-09/.writeCommitted; tryf "(c) p and marker NUL" cellBlastFoam; echo "   dirs: $(ls -da [1-9]* 2>/dev/null | tr '\n' ' ')"
fresh; nul 2e-09/uniform/time; tryf "(d) uniform/time NUL" cellBlastFoam; echo "   dirs: $(ls -da [1-9]* 2>/dev/null | tr '\n' ' ')"
fresh; f=postProcessing/fsi/0/coupling.dat; s=$(stat -c %s $f); /usr/bin/python3 -c "
import sys; b=bytearray(open('$f','rb').read()); b[-300:]=b'\0'*300; open('$f','wb').write(b)"
tryf "(e) coupling.dat tail NUL" cellBlastFoam; echo "   dirs: $(ls -da [1-9]* 2>/dev/null | tr '\n' ' '); NUL bytes in coupling.dat now: $(tr -cd '\000' < $f | wc -c)"

#!/bin/bash
# g31 (class 1+2, the user deletes the latest time): finished blast to 2 ns; the user removes 2e-09/ (rm -r, or foamListTimes -rm -time 2e-09), restart to 3 ns from 1e-09: solid.h5 and the logs cut back to 1e-09 and the run continued equal to a clean run to 3 ns?
. "$(dirname "$0")/../lib.sh"
blastRef; cd $W/r; cp -r ref2 k; cd k; rm -r 2e-09; latest; blastEnd 3e-9 1e-9
tryf "restart after 2e-09 removed" cellBlastFoam; echo "   times $(ls -d [1-9]* | tr '\n' ' '), solid.h5 $(h5steps solid/solid.h5) steps, xmf $(xmfsteps solid/solid.xmf)"; cmpRef $W/r/ref
cd ..; cp -r ref2 k2; cd k2; foamListTimes -rm -time 2e-09 > /dev/null 2>&1; echo "   foamListTimes -rm: times $(ls -d [1-9]* | tr '\n' ' ')"; latest; blastEnd 3e-9 1e-9; tryf "restart after foamListTimes -rm" cellBlastFoam; cmpRef $W/r/ref

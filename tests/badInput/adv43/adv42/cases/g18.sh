#!/bin/bash
# g18 (class 1+2, a restart killed at every stage of its start-up, then restarted): finished blast to 2 ns; for each delay d a fresh copy, the restart to 3 ns SIGKILLed d s after its start, then the same restart again: the result equal (bitwise) to a clean restart's?
. "$(dirname "$0")/../lib.sh"
blastRef; cd $W/r
for d in 0.03 0.1 0.2 0.35 0.5 0.8 1.2 2; do
  rm -rf k; cp -r ref2 k; cd k; latest; blastEnd 3e-9 1e-9; killAt $d cellBlastFoam > /dev/null; echo "d=$d: times $(ls -d [1-9]* | tr '\n' ' '), hidden $(ls -d .[0-9]* 2>/dev/null | tr '\n' ' ')"
  tryf "   restart again" cellBlastFoam; cmpRef $W/r/ref; cd ..
done

#!/bin/bash
# q07: -overwrite with SYMBOLIC LINKS the user put in the function objects' folders: postProcessing/fsi/0/archive -> a folder OUTSIDE the case holding the user's files; postProcessing/solidProbes/0/ref.dat -> a file outside; are the outside files kept (no removal through the link)?
. "$(dirname "$0")/../lib.sh"
blastDone; mkdir -p $W/outside/archive; echo "q07 archived run" > $W/outside/archive/old.dat; echo "q07 reference" > $W/outside/ref.dat
ln -s $W/outside/archive postProcessing/fsi/0/archive; ln -s $W/outside/ref.dat postProcessing/solidProbes/0/ref.dat
tryf "-overwrite" cellBlastFoam -overwrite
echo "   outside: $(ls -R $W/outside | tr '\n' ' ') | $(cat $W/outside/archive/old.dat $W/outside/ref.dat 2>&1 | tr '\n' ' ')"; echo "   links: $(ls -l postProcessing/fsi/0 postProcessing/solidProbes/0 2>&1 | grep -c -- '->')"

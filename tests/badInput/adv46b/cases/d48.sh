#!/bin/bash
# d48 (class 5, solid result files cut or damaged, indentation): (a) solid.h5 truncated to half: solidToFoam refused naming the file; (b) restart.h5 truncated to half and a restart: refused naming restart.h5; (c) solid.xmf replaced by an empty file: solidToFoam (reads the .h5) fine or a clear word; a restart refused or the xmf rewritten.
. "$(dirname "$0")/../lib.sh"
idn; h=postProcessing/indentation/solid.h5; truncate -s $(( $(stat -c %s $h) / 2 )) $h; tryt 60 "(a) solidToFoam, solid.h5 cut" solidToFoam $h
cd $W; rm -rf ind; ik; r=postProcessing/indentation/restart.h5; truncate -s $(( $(stat -c %s $r) / 2 )) $r; tryt 100 "(b) restart, restart.h5 cut" cellIndentationFoam; after
cd $W; rm -rf ind; ik; : > postProcessing/indentation/solid.xmf; tryt 200 "(c) restart, solid.xmf empty" cellIndentationFoam; after; echo "   xmf steps $(xmfsteps postProcessing/indentation/solid.xmf), h5 steps $(h5steps postProcessing/indentation/solid.h5)"

#!/bin/bash
# f52 (class 1/5, an older solid.xmf restored): the finished preview's solid/solid.xmf replaced by the one it had after its first write (1 step; saved from a copy run to 1e-9), restart to 3e-9: solid.xmf at the end lists every step of solid.h5 (3), or the restart refuses naming solid.xmf; never an xmf that lists fewer steps than solid.h5 without a word.
# (corrected after its first run: bd copied into the folder of the first run, which was restarted instead)
. "$(dirname "$0")/../lib.sh"
blast; blastEnd 1e-9 1e-9; tryt 200 "a run to 1e-9" cellBlastFoam; cp solid/solid.xmf $W/xmf1; cd $W; mv blast first; echo "   xmf1 steps $(xmfsteps $W/xmf1)"
bd; rs; cp $W/xmf1 solid/solid.xmf; tryt 240 "restart with the 1-step xmf" cellBlastFoam; cont; after; echo "   xmf steps $(xmfsteps solid/solid.xmf), h5 steps $(h5steps solid/solid.h5)"

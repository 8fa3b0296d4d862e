#!/bin/bash
# z10: blast run to 2 ns; solid/solid.xmf (a) removed, (b) cut in its middle (a copy that did not finish), then a restart to 3 ns: solid.xmf rebuilt from solid.h5 (every step listed, the same count as solid.h5), exit 0? and solidToFoam on the result
. "$(dirname "$0")/../lib.sh"
blastDone; latest; blastEnd 3e-9 1e-9; cp -r . ../keep
rm solid/solid.xmf; try "(a) xmf removed, restart" cellBlastFoam; echo "   solid.h5 steps $(h5steps solid/solid.h5), solid.xmf times $(xmfsteps solid/solid.xmf)"
try "(a) solidToFoam" solidToFoam solid/solid.h5
cd $W; rm -rf blast; cp -r keep blast; cd blast; head -c $(( $(stat -c %s solid/solid.xmf) / 2 )) solid/solid.xmf > x; mv x solid/solid.xmf
try "(b) xmf cut, restart" cellBlastFoam; echo "   solid.h5 steps $(h5steps solid/solid.h5), solid.xmf times $(xmfsteps solid/solid.xmf); xml parses: $(/usr/bin/python3 -c "import xml.etree.ElementTree as E; E.parse('solid/solid.xmf'); print('yes')" 2>&1 | tail -1)"

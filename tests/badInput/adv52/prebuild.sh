#!/bin/bash
# prebuild.sh PREFIX: the bases, as adv51's (the earlier passes' prebuild.sh called unchanged with my prefix), with one step
# before them:
# adv35's blastBase (the preview prepared by tests/blast/runPreview.sh with -Z 20e-6) is built first and the water probe
# its Allrun keeps (written into system/controlDict.allrun, the two probes above the 20 um column dropped) is put into
# system/controlDict itself (one probe a line, as the tutorial writes them: adv51 n02's edit finds them), so that the earlier passes' blastEnd, which rewrites controlDict.allrun, keeps the same probe
# (adv51 phase 2 did this by hand at 09:42: without it every restart after blastEnd is refused "probeLocations (changed)")
here=$(cd "$(dirname "$0")" && pwd); P=${1:-/tmp/adv52-}
ADV=${P}adv35 nice -n 10 bash -c ". $here/../adv35/lib.sh; rmdir \$W" || exit 1
c=${P}adv35/blastBase/axisymmetricPreview
if grep -q probeLocations $c/system/controlDict.allrun 2>/dev/null; then
  /usr/bin/python3 - $c/system/controlDict $c/system/controlDict.allrun <<'PY' || exit 1
import re, sys
cd, ca = sys.argv[1:3]
a = open(ca).read(); m = re.search(r'probeLocations\s*\((.*?)\)\s*;\s*\}\s*\}', a, re.S)
keep = m.group(1).strip()
t = open(cd).read(); n = re.search(r'probeLocations\s*\((.*?)\n\s*\);', t, re.S)
t = t[:n.start()] + 'probeLocations\n        (\n            ' + keep + '\n        );' + t[n.end():]
open(cd, 'w').write(t)
a = re.sub(r'functions\s*\{\s*fluidProbes\s*\{\s*probeLocations\s*\(.*?\)\s*;\s*\}\s*\}\s*', '', a, flags=re.S)
open(ca, 'w').write(a); print('probe kept in controlDict:', keep)
PY
fi
# adv35's lib.sh called with ADV=<prefix>adv47b (where adv47b's and later passes' bases lie) would build a second,
# unpatched blastBase: the patched one is copied there first
mkdir -p ${P}adv47b; for b in indBase blastBase; do [ -e ${P}adv47b/$b ] || cp -a ${P}adv35/$b ${P}adv47b/$b; done
# then adv51's prebuild.sh without its adv49b step (sbd, xbd, mbd: three previews run to 5 ns that no case I run uses):
# adv48a's, adv48b's and adv50b's prebuild.sh, unchanged, with my prefix
bash $here/../adv48a/prebuild.sh $P && bash $here/../adv48b/prebuild.sh $P && bash $here/../adv50b/prebuild.sh $P

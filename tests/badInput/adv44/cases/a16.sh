#!/bin/bash
# a16 (class 2, planeWave -inflow -overwrite through a SYMBOLIC LINK): a blast case whose constant/inflowWave is a link to a shared file OUTSIDE the case ($W/shared/inflowWave, written by the Allrun (-Z 40e-6 -inflow 20e-6) and then edited: a comment line and one data row changed); planeWave -inflow 10e-6 without, then with -overwrite: the shared file outside the case written through the link, or the link replaced, and said?
. "$(dirname "$0")/../lib.sh"
iblast; mkdir -p $W/shared; mv constant/inflowWave $W/shared/inflowWave; echo "// a16 the shared wave, my notes" >> $W/shared/inflowWave; ln -s $W/shared/inflowWave constant/inflowWave; md5sum $W/shared/inflowWave > ../m
tryf "planeWave -inflow again (link, same wave + a comment)" planeWave $IW; echo "   link: $(readlink constant/inflowWave || echo 'no longer a link'); shared: $(md5sum -c ../m 2>&1 | awk '{print $2}')"
/usr/bin/python3 - $W/shared/inflowWave <<'P'
import sys, re; p = sys.argv[1]; L = open(p).read().split('\n'); i = [k for k, l in enumerate(L) if re.match(r'\s*\(\s*[-0-9.eE+]+\s+[-0-9.eE+]+', l)][5]; L[i] = L[i].replace('(', '( ', 1); L.insert(i, '    // a16 edited here'); open(p, 'w').write('\n'.join(L))
P
md5sum $W/shared/inflowWave > ../m; tryf "planeWave -inflow -overwrite (link to the edited shared file)" planeWave $IW -overwrite; echo "   link: $(readlink constant/inflowWave || echo 'no longer a link'); shared: $(md5sum -c ../m 2>&1 | awk '{print $2}')"; where "a16 the shared wave, my notes"

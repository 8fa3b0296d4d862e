#!/bin/bash
# w76: blast probes: probeLocations () empty, a probe outside the domain (1 1 0), the fields list empty ()
. "$(dirname "$0")/../lib.sh"
blast; f=system/controlDict; cp $f ../cd; /usr/bin/python3 - <<'P'
import re; s=open('system/controlDict').read(); s=re.sub(r'probeLocations\s*\([^;]*?\)\s*;', 'probeLocations ();', s, count=1, flags=re.S); open('system/controlDict','w').write(s)
P
try "probeLocations ()" cellBlastFoam; cp ../cd $f; sed -i 's/(1e-7 90e-6 0) /(1 1 0) /' $f; try "probe (1 1 0)" cellBlastFoam; cp ../cd $f; sed -i 's/fields          (p);/fields ();/' $f; try "fields ()" cellBlastFoam

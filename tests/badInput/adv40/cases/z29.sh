#!/bin/bash
# z29: solid.h5 damage that Fletcher-32 cannot see (a 16-bit word 0x0000 turned into 0xffff inside /steps/1/region's (or displacement's) data; reliability.md: digest64 catches it): solidToFoam, the Python reader (neuronFsi.solidResults, used by pulseStudy's indicators), and a restart to 3 ns: each refused naming the file and dataset?
. "$(dirname "$0")/../lib.sh"
blastDone; /usr/bin/python3 - solid/solid.h5 <<'P'
import h5py, sys
f = h5py.File(sys.argv[1], 'r'); done = False
for name, size in (('steps/1/region', 4), ('steps/1/displacement', 8)):
    d = f[name]; off = d.id.get_chunk_info(0).byte_offset if d.chunks else d.id.get_offset(); n = d.id.get_storage_size()
    b = bytearray(open(sys.argv[1], 'rb').read())
    for k in range(off, off + n - size + 1, size):   # a value whose low 16-bit word is 0x0000 -> 0xffff (Fletcher-32 sums words mod 65535)
        if b[k:k+2] == b'\0\0':
            b[k:k+2] = b'\xff\xff'; open(sys.argv[1], 'wb').write(b); print("swapped the low word of the value at byte", k, "of", name); done = True; break
    if done: break
f.close()
if not done: print("no such word found")
P
try "solidToFoam" solidToFoam solid/solid.h5
PYTHONPATH=$ROOT/src/python try "neuronFsi.solidResults field(1, region)" /usr/bin/python3 -c "
from neuronFsi.solidResults import SolidResults
with SolidResults('solid/solid.h5') as r: v = r.field(1, 'region'); print('read', v.shape)"
latest; blastEnd 3e-9 1e-9; try "restart" cellBlastFoam

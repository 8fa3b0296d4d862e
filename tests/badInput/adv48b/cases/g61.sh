#!/bin/bash
# g61 (class 5, a damaged probe log read by the post-processing) bd with 64 zero bytes in the middle of postProcessing/fluidProbes/0/p (a power loss), then planeWave -check: refused naming the file and the damaged line; never error measures computed from the damaged rows. Then the restart to 3e-9: refused naming the log (its bytes are not its commit's) or the damage said.
. "$(dirname "$0")/../lib.sh"
bd; rs; f=postProcessing/fluidProbes/0/p; n=$(stat -c %s $f); /usr/bin/python3 -c "import sys; p=sys.argv[1]; b=bytearray(open(p,'rb').read()); o=len(b)//2; b[o:o+64]=bytes(64); open(p,'wb').write(b)" $f; echo "   $f: $n bytes, 64 zeroed at $((n/2))"
tryt 120 "planeWave -check" planeWave -case . -check; tail -3 $W/try.log | cut -c1-200
sums > ../s0; tryt 240 "restart" cellBlastFoam; cont; echo "   changed: $(changed ../s0)"

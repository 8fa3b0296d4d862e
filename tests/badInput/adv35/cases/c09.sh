#!/bin/bash
# c09: cellBlastFoam running while plotBlast.py reads its probes
. "$(dirname "$0")/../lib.sh"
blast; setd system/controlDict endTime 1e-8
cellBlastFoam > log.a 2>&1 & p=$!; sleep 1; /usr/bin/python3 "$ROOT/tutorials/blast/plotBlast.py" . > log.plot 2>&1; echo "plot rc=$?"; tail -3 log.plot; wait $p; echo "run rc=$?"

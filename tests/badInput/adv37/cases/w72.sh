#!/bin/bash
# w72: blast: writeInterval 1e-15 s over a 2 ns run (2e6 writes of ~0.4 MB: about 800 GB): refused or bounded before the run (class 6), or writes until the disk fills? (30 s timeout)
. "$(dirname "$0")/../lib.sh"
blast; printf 'endTime 2e-9;\nwriteInterval 1e-15;\n' > system/controlDict.allrun; timeout -s KILL 30 cellBlastFoam > log.a 2>&1; echo "rc=$?"; fatal log.a 4; echo "time directories after 30 s: $(ls -d [1-9]* 2>/dev/null | wc -l), $(du -sh . | cut -f1)"

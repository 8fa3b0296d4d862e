#!/bin/bash
# y04: preview Allrun SIGKILLed in its solver; log.cellBlastFoam.running then holds pid 1 (a live process NOT in the case: pid reuse); ./Allrun again: refused as stopped before its end, or "still running (pid 1)"?
. "$(dirname "$0")/../lib.sh"
killedAllrun 2e-09; echo 1 > log.cellBlastFoam.running; again a2

#!/bin/bash
# y01: preview Allrun SIGKILLed in its solver; the user removes log.cellBlastFoam.running and leaves an EMPTY log.cellBlastFoam.status (a half-written mark); ./Allrun again: the solver refused/re-run, or skipped as ended?
. "$(dirname "$0")/../lib.sh"
killedAllrun 2e-09; rm -f log.cellBlastFoam.running; : > log.cellBlastFoam.status; again a2

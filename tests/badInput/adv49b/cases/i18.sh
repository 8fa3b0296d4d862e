#!/bin/bash
# i18 (class 4, motionDistance at the edges, in fsiProperties): a blast copy (the bd preview) run for 2e-11 s with motionDistance 0, -5e-6, 1e-300, 1e-320 (denormal), 1e300, 4e-5 (beyond the column: every
# fluid point moves), and motionNearest 0, 1, 100000: each refused naming constant/fsiProperties, interface/<entry>, the value
# and the range, or run (exit 0, finite coupling.dat); no crash, no sigFpe.
. "$(dirname "$0")/../lib.sh"
blast; short; cp constant/fsiProperties ../f0
for e in "motionDistance 0" "motionDistance -5e-6" "motionDistance 1e-300" "motionDistance 1e-320" "motionDistance 1e300" "motionDistance 4e-5" "motionNearest 0" "motionNearest 1" "motionNearest 100000"; do
  cp ../f0 constant/fsiProperties; fsiSet $e > /dev/null; tryt 200 "[$e]" cellBlastFoam
  echo "   ran: $(ls -d [1-9]* 2>/dev/null | tr '\n' ' ')| coupling rows $(nLines postProcessing/fsi/0/coupling.dat) | $(grep -a -i -m1 'band\|motion' $W/try.log | cut -c1-160)"; rm -rf [1-9]* solid postProcessing; done

#!/bin/bash
# o07: blast: -overwrite with startTime 1e-09 (redo the second half): solid.h5/xmf must hold t = 0, 1 ns (old) and 2 ns (new), the probes the new 1-2 ns rows once
. "$(dirname "$0")/../lib.sh"
blastDone; setd system/controlDict startTime 1e-09
cellBlastFoam -overwrite > log.ow 2>&1; echo "rc=$?"; tail -2 log.ow; ls -d [0-9]*
h5ls solid/solid.h5/steps; for s in $(h5ls solid/solid.h5/steps | awk '{print $1}'); do h5dump -a /steps/$s/time solid/solid.h5 2>/dev/null | grep -A1 DATA | tail -1; done
grep -o 'Time Value="[^"]*"' solid/solid.xmf
ls postProcessing/solidProbes postProcessing/fluidProbes; f=$(ls postProcessing/solidProbes/0/*); grep -v '^#' $f | awk '{print $1}' | sort -g | uniq -d | head -3; echo "dup times above (if any)"; grep -v '^#' $f | tail -2 | cut -c1-60

#!/bin/bash
# CASETIMEOUT=600
# n26 (new, class 2/3: result FILES (not folders) that are links to another case's - a user linking "the reference run's
# force.dat" into a new case; fix19j checks folders): A = idn (finished); B = a fresh copy of its inputs with
# postProcessing/indentation/force.dat and force.dat.fnv1a64 symbolic links to A's; (a) cellIndentationFoam in B; (b)
# the same with -overwrite; (c) the blast: bd with
# postProcessing/fluidProbes/0/p a link to a copy A2 of it, B restarted to 3e-9. Expected: refused (a result file whose
# real path leaves the case) or the link replaced by B's own file; A's force.dat / A2's log changed = DATALOSS.
. "$(dirname "$0")/../lib.sh"
idn; A=$PWD; md5sum postProcessing/indentation/* > $W/mA; cd $W; mkdir B; cp -r $A/system $A/constant B/; cd B; mkdir -p postProcessing/indentation; for f in force.dat force.dat.fnv1a64; do ln -s $A/postProcessing/indentation/$f postProcessing/indentation/$f; done
tryt 300 "(a) B with force.dat (+sidecar) links to A's" cellIndentationFoam; echo "   End $(grep -a -c '^End' $W/try.log) | said: $(say 2 | cut -c1-250) | A: $(cd $A; md5sum -c $W/mA 2>&1 | grep -v ': OK$' | tr '\n' ' ' | cut -c1-200)"
tryt 300 "(b) the same with -overwrite" cellIndentationFoam -overwrite; echo "   End $(grep -a -c '^End' $W/try.log) | said: $(say 2 | cut -c1-250) | A: $(cd $A; md5sum -c $W/mA 2>&1 | grep -v ': OK$' | tr '\n' ' ' | cut -c1-200) | B's force.dat: $(stat -c %F postProcessing/indentation/force.dat)"
cd $W; bd; cp -a . $W/A2; rm postProcessing/fluidProbes/0/p; ln -s $W/A2/postProcessing/fluidProbes/0/p postProcessing/fluidProbes/0/p; md5sum $W/A2/postProcessing/fluidProbes/0/p > $W/mA2; rs; rm -f .runLock
tryt 300 "(c) bd restarted with its probe log a link to a copy's" cellBlastFoam; echo "   End $(grep -a -c '^End' $W/try.log) | said: $(say 2 | cut -c1-250) | A2's log: $(md5sum -c $W/mA2 2>&1 | sed 's/.*: //')"

#!/bin/bash
# CASETIMEOUT=900
# m08 (fix19g's whole numbers as written and the function objects' step counts, adv49a j06 / adv50a k04, varied beyond
# the label's top): (a) fluidProbes' writeInterval (writeControl timeStep) -1, -2147483649, 0, 1e-320, nan, 1.5, "1 2",
# 0x10; (b) its executeControl timeStep with executeInterval 0, -1, 2147483647.0; (c) controlDict's purgeWrite 2147483648
# and -1, writePrecision 0, 31, -1, 2147483648, timePrecision 0, 2147483648; (d) the smoke indentation's controlDict
# fieldWriteInterval and checkpointInterval 2147483648, 1e400, nan, -1, maxSteps 2147483648, 9223372036854775808, 0;
# (e) the sod tube's writeInterval (writeControl timeStep) 0 and -1. Each: refused rc 1 naming the file, the entry, the
# digits as written and the range (or accepted where the range takes it); never a signal, never a value cut or wrapped.
. "$(dirname "$0")/../lib.sh"
res() { echo "   sig: $(sig) | End: $(grep -a -c '^End' $W/try.log) | times: $(ls -d [0-9]* 2>/dev/null | tr '\n' ' ') | msg: $(msg 4 | cut -c1-450)"; }
blast; short; rm -f .runLock; cp -a . ../b0; hdr0 system/controlDict
back() { cd $W; rm -rf $1; cp -a $2 $1; cd $1; }
for v in -1 -2147483649 0 1e-320 nan 1.5 "1 2" 0x10; do subset system/controlDict fluidProbes writeInterval "$v" > /dev/null; hdr system/controlDict | grep CHANGED
  tryt 90 "(a) fluidProbes writeInterval '$v' (timeStep)" cellBlastFoam; res; back blast b0; done
for v in 0 -1 2147483647.0; do subset system/controlDict fluidProbes executeControl timeStep > /dev/null; subset system/controlDict fluidProbes executeInterval "$v" > /dev/null
  tryt 90 "(b) fluidProbes executeControl timeStep, executeInterval '$v'" cellBlastFoam; res; back blast b0; done
for kv in "purgeWrite 2147483648" "purgeWrite -1" "writePrecision 0" "writePrecision 31" "writePrecision -1" "writePrecision 2147483648" "timePrecision 0" "timePrecision 2147483648"; do set -- $kv
  grep -q "^$1 " system/controlDict && sete system/controlDict $1 $2 > /dev/null || echo "$1 $2;" >> system/controlDict; tryt 90 "(c) controlDict $1 $2" cellBlastFoam; res; back blast b0; done
cd $W; ind; rm -f .runLock; cp -a . ../i0; grep -n "fieldWriteInterval\|checkpointInterval\|maxSteps" system/controlDict | sed 's/^/   ind controlDict: /'
for kv in "fieldWriteInterval 2147483648" "fieldWriteInterval 1e400" "fieldWriteInterval nan" "fieldWriteInterval -1" "checkpointInterval 2147483648" "checkpointInterval 1e400" "checkpointInterval -1" "checkpointInterval 0" "maxSteps 2147483648" "maxSteps 9223372036854775808" "maxSteps 0"; do set -- $kv
  grep -q "^$1 " system/controlDict && sete system/controlDict $1 $2 > /dev/null || echo "$1 $2;" >> system/controlDict
  tryt 120 "(d) indentation controlDict $1 $2" cellIndentationFoam; echo "   sig: $(sig) | End: $(grep -a -c '^End' $W/try.log) | force rows: $(nLines postProcessing/indentation/force.dat) | msg: $(msg 4 | cut -c1-450)"; back ind i0; done
cd $W; sod; rm -f .runLock; cp -a . ../s0
for v in 0 -1; do sed -i '/^writeControl /d; /^writeInterval /d' system/controlDict; printf 'writeControl timeStep;\nwriteInterval %s;\n' $v >> system/controlDict
  tryt 90 "(e) sod writeControl timeStep, writeInterval $v" rhoRiemannFoam; res; back sod s0; done

#!/bin/bash
# CASETIMEOUT=900
# j06 (class 4, fix19e's label reader (adv48b g40, g42) varied: every whole-number entry we read, at 2^31-1, 2^31, 2^63):
# the prepared preview (blast, endTime 2e-11): fsiProperties coupling/maxIter, coupling/solidSubcycles,
# interface/motionNearest, interface/pressureQuadrature, coupling/reuse (scheme IQNILS); controlDict purgeWrite,
# writePrecision, timePrecision (cellBlastFoam); cellMeshDict membraneLayers, maxElements (cellMesh); the 3D quarter's
# cellMeshDict hexCoeffs/maxCells or fluid/maxCells (cellMesh); the smoke indentation's controlDict checkpointInterval
# uniform/solidState h5Step (bd, -acceptEdited). Each value outside the entry's range refused rc 1 naming the file, the
# entry, the digits given and the range (beyond the label: named as such); inside it accepted (the run starts: killed
# at 60 s or ends); never a wrapped value, never a signal.
. "$(dirname "$0")/../lib.sh"
V="2147483647 2147483648 9223372036854775808"
blast; short; rm -f .runLock; cp -a . ../b0
go() { tryt 60 "$1 = $2: $3" "${@:3}"; echo "   sig: $(sig) | msg: $(msg 4 | cut -c1-500)"; [ -d 1e-11 ] || [ -d 2e-11 ] && echo "   (the run wrote times: $(ls -d [0-9]* | tr '\n' ' '))"; cd $W; rm -rf blast; cp -a b0 blast; cd blast; }
for e in coupling/maxIter coupling/solidSubcycles interface/motionNearest interface/pressureQuadrature; do for v in $V; do subset constant/fsiProperties ${e%/*} ${e#*/} $v > /dev/null; go $e $v cellBlastFoam; done; done
for v in $V; do subset constant/fsiProperties coupling scheme IQNILS > /dev/null; subset constant/fsiProperties coupling reuse $v > /dev/null; go "coupling/reuse (IQNILS)" $v cellBlastFoam; done
for e in purgeWrite writePrecision timePrecision; do for v in $V; do sete system/controlDict $e $v; go $e $v cellBlastFoam; done; done
for e in membraneLayers maxElements; do for v in $V; do sed -i "/^$e /d" system/cellMeshDict; sed -i "/^#sinclude/i $e $v;" system/cellMeshDict; go $e $v cellMesh; done; done
cd $W; ind; rm -f .runLock; cp -a . ../i0
for v in $V; do sed -i "/^checkpointInterval /d" system/controlDict; echo "checkpointInterval $v;" >> system/controlDict; tryt 60 "checkpointInterval = $v: cellIndentationFoam" cellIndentationFoam; echo "   sig: $(sig) | msg: $(msg 4 | cut -c1-500) | results: $(ls postProcessing/indentation 2>/dev/null | tr '\n' ' ')"; cd $W; rm -rf ind; cp -a i0 ind; cd ind; done
cd $W; q; rm -f .runLock; grep -n "maxCells\|Coeffs\|^fluid\|^ *{" system/cellMeshDict | head -8 | tr '\n' ' '; echo; cp -a . ../q0
for v in $V; do for s in hexCoeffs fluid; do grep -q "^ *$s" system/cellMeshDict || continue; subset system/cellMeshDict $s maxCells $v; tryt 60 "$s/maxCells = $v: cellMesh" cellMesh; echo "   sig: $(sig) | msg: $(msg 4 | cut -c1-500)"; cd $W; rm -rf q; cp -a q0 q; cd q; done; done
cd $W; bd; rs; rm -f .runLock; cat 2e-09/uniform/solidState | grep -a h5Step; cp -a . ../bd0
for v in $V; do sete 2e-09/uniform/solidState h5Step $v; tryt 90 "2e-09/uniform/solidState h5Step = $v: cellBlastFoam -acceptEdited" cellBlastFoam -acceptEdited; echo "   sig: $(sig) | msg: $(msg 4 | cut -c1-500) | times: $(ls -d [0-9]* | tr '\n' ' ')"; cd $W; rm -rf blast; cp -a bd0 blast; cd blast; done

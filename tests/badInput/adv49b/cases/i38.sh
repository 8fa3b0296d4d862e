#!/bin/bash
# i38 (class 4/SILENT, labels beyond 32 bits in controlDict and the Python tools): a blast copy run for 2e-11 s with
# writeControl timeStep and writeInterval 4294967297 (every step if cut to 1), maxWrites 4294967297, purgeWrite 4294967297;
# pulseStudyDict nProcs 4294967298; calibrationDict nProcs 4294967298 and maxIterations 4294967297; calibrateCell -nProcs
# 4294967298; sweepCase -nProcs 4294967298 and -maxRuns 4294967297: each refused naming the entry/option and the range, or
# (Python, no 32-bit limit) taken as the number it is (then no more processes than points or values); never cut to 1 or 2.
. "$(dirname "$0")/../lib.sh"
blast; short; cp system/controlDict ../c0
for e in "writeControl timeStep|writeInterval 4294967297" "maxWrites 4294967297" "purgeWrite 4294967297"; do cp ../c0 system/controlDict; IFS='|' read -ra kv <<< "$e"
  for x in "${kv[@]}"; do set -- $x; sed -i "/^$1 /d" system/controlDict; echo "$1 $2;" >> system/controlDict; done; grep -v '^ *$' system/controlDict.allrun | tr '\n' ' ' | sed 's/^/   allrun: /'; echo
  tryt 120 "[$e]" cellBlastFoam; echo "   times: $(ls -d [1-9]* 2>/dev/null | wc -l)"; rm -rf [1-9]* solid postProcessing; done
study; setStudy nProcs 4294967298; tryt 120 "pulseStudy nProcs 4294967298" pulseStudy; echo "   study folder: $(ls postProcessing/pulseStudy 2>/dev/null | tr '\n' ' ')"; killIn $W/study
cal; sete system/calibrationDict nProcs 4294967298; tryt 60 "calibrationDict nProcs 4294967298" calibrateCell; killIn $W/cal
cp ../../cal/system/calibrationDict system/ 2>/dev/null; sete system/calibrationDict nProcs 2; sete system/calibrationDict maxIterations 4294967297; tryt 60 "maxIterations 4294967297" calibrateCell; killIn $W/cal
sete system/calibrationDict maxIterations 20; tryt 60 "calibrateCell -nProcs 4294967298" calibrateCell -nProcs 4294967298; killIn $W/cal
bd; tryt 60 "sweepCase -nProcs 4294967298" sweepCase -entry constant/fsiProperties/coupling/maxIter -values "30 31" -output x=postProcessing/fsi/0/coupling.dat:-1:1 -name n1 -run "true" -nProcs 4294967298
tryt 60 "sweepCase -maxRuns 4294967297" sweepCase -entry constant/fsiProperties/coupling/maxIter -values "30 31" -output x=postProcessing/fsi/0/coupling.dat:-1:1 -name n2 -run "true" -maxRuns 4294967297; echo "   sweep: $(ls postProcessing/sweep 2>/dev/null | tr '\n' ' ')"

#!/bin/bash
# CASETIMEOUT=900
# h10 (class 4, adv47b f25/f64 varied: the uncertainty's step and checkStep at and past their edges; the tutorial's
# pulseStudyDict.uncertainty on the small study, maxPoints 1 appended so that nothing runs): step 2.220446049250313e-16
# (the least step f25's message suggests), 1.1e-16, 0, -1e-3, nan, inf, 1e308, 1e3 (exp overflow in ln p: e^1000), 710;
# checkStep 1e-17 with a good step; step 1e-17 with the parameters' log no. Each refused naming step/checkStep, the
# parameter and the valid range (or only maxPoints if the step is valid); no Traceback.
. "$(dirname "$0")/../lib.sh"
study; cp $ROOT/tutorials/blast/pulseStudy/system/pulseStudyDict.uncertainty system/; echo "maxPoints 1;" >> system/pulseStudyDict.uncertainty; cp system/pulseStudyDict.uncertainty ../u0
grep -a -n "step\|log " ../u0 | head -8 | cut -c1-120
show() { local rc=$1; echo "   [$2] rc=$rc traceback=$(grep -a -c Traceback $W/try.log) | $(grep -a -m1 -A2 '[Ee]rror\|refused\|outside\|not a\|invalid\|must\|maxPoints\|step' $W/try.log | grep -av '^ *$' | head -2 | tr '\n' ' ' | tr -s ' ' | cut -c1-330)"; }
for v in 2.220446049250313e-16 1.1e-16 0 -1e-3 nan inf 1e308 1e3 710; do cp ../u0 system/pulseStudyDict.uncertainty; sed -i "s/^    step .*/    step        $v;/" system/pulseStudyDict.uncertainty
  timeout -s KILL 30 pulseStudy -dict system/pulseStudyDict.uncertainty > $W/try.log 2>&1; show $? "step $v"; killIn $W; done
cp ../u0 system/pulseStudyDict.uncertainty; sed -i "s/^    checkStep .*/    checkStep   1e-17;/" system/pulseStudyDict.uncertainty; timeout -s KILL 30 pulseStudy -dict system/pulseStudyDict.uncertainty > $W/try.log 2>&1; show $? "checkStep 1e-17"
cp ../u0 system/pulseStudyDict.uncertainty; sed -i "s/^    step .*/    step        1e-17;/; s/log *yes;/log no;/g" system/pulseStudyDict.uncertainty; echo "   log no: $(grep -c 'log no' system/pulseStudyDict.uncertainty)"; timeout -s KILL 30 pulseStudy -dict system/pulseStudyDict.uncertainty > $W/try.log 2>&1; show $? "step 1e-17, log no"

#!/bin/bash
# i58 (class 3/2, i40 sharpened: pulseStudy SIGKILLed while its point's solver runs, resumed at once): the small study with one
# point and a 20 ns end (baseOptions -endTime 2e-8: the solver runs for many seconds), pulseStudy SIGKILLed once the point's
# cellBlastFoam process is seen; checked that the orphan still runs, then the study resumed at once (60 s): refused naming the
# running process (its process group), nothing moved, the orphan untouched - never the running case moved aside to
# case.interrupted and the point run again beside it. Then the orphan killed and the study resumed: the point runs (exit 0).
. "$(dirname "$0")/../lib.sh"
study; setStudy baseOptions "(-h 0.25e-6 -far 2e-6 -dz 0.25e-6 -cell 0.5e-6 -Z 20e-6 -endTime 2e-8)"; P=postProcessing/pulseStudy/points
pulseStudy > ../log.s1 2>&1 & p=$!; for i in $(seq 3000); do inDir $W/study | tr ';' '\n' | grep -q '^ *[0-9]*:cellBlastFoam' && break; sleep 0.1; done
kill -KILL $p; wait $p 2>/dev/null; sleep 0.5; echo "   after ~$((i/10)) s: pulseStudy SIGKILLed; running under the study: $(inDir $W/study | tr ';' '\n' | grep -c ':') processes, solver: $(inDir $W/study | tr ';' '\n' | grep -o '[0-9]*:cellBlastFoam' | head -1)"
snap ../snap0; tryt 60 "resume while the orphan runs" pulseStudy; sed -n 1,6p $W/try.log | cut -c1-220 | sed 's/^/   /'
echo "   moved/removed: $(gone ../snap0 | tr '\n' ' ' | cut -c1-300) | aside: $(ls -d $P/*/case.interrupted* 2>/dev/null | tr '\n' ' ') | solver still running: $(inDir $W/study | tr ';' '\n' | grep -o '[0-9]*:cellBlastFoam' | head -1)"
killIn $W/study; sleep 1; tryt 600 "resume after the orphan was killed" pulseStudy; tail -3 $W/try.log | cut -c1-200 | sed 's/^/   /'; echo "   points: $(ls $P/* | tr '\n' ' ')"

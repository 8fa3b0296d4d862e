#!/bin/bash
# i40 (class 3/2, pulseStudy SIGKILLed: its point's solver runs on): the small study with two points, SIGKILLed (pulseStudy
# alone) while its first point's cellBlastFoam runs; resumed at once with nProcs 2 and a changed threshold: refused naming the
# running process (the earlier run not ended), nothing moved or removed while it runs; after that process ends (killed
# by the case), the resume runs both points (the killed point from a fresh copy, its old copy aside) and exits 0.
. "$(dirname "$0")/../lib.sh"
study; setStudy overpressure "(30e6 40e6)"; P=postProcessing/pulseStudy/points
pulseStudy > ../log.s1 2>&1 & p=$!; for i in $(seq 3000); do inDir $W/study | grep -q cellBlastFoam && break; sleep 0.1; done; echo "   solver seen after ~$((i/10)) s"
sleep 0.3; kill -KILL $p; wait $p 2>/dev/null; echo "   pulseStudy SIGKILLed; left running here: $(inDir $W/study)"; snap ../snap0
setStudy nProcs 2; sed -i 's/value       0.21 \[-\];/value       0.2 [-];/' system/pulseStudyDict; tryt 120 "resume while the orphan runs" pulseStudy; echo "   moved/removed: $(gone ../snap0 | tr '\n' ' ') | running: $(inDir $W/study)"
killIn $W/study; sleep 1; tryt 900 "resume after the orphan ended" pulseStudy; tail -3 $W/try.log | cut -c1-200 | sed 's/^/   /'; echo "   points: $(ls $P | tr '\n' ' ') | aside: $(ls -d $P/*/case.interrupted* 2>/dev/null | tr '\n' ' ')"

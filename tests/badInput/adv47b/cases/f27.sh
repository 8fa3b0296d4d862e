#!/bin/bash
# f27 (class 3, a study SIGKILLed and resumed at once): pulseStudy (one point, 30 MPa 2 ns on the small preview) started; once the point's solver runs, the pulseStudy process alone is SIGKILLed (its point's Allrun and solver go on); the same pulseStudy started again at once: refused naming the earlier run still going (process group / lock), nothing moved aside or run twice in one folder.
. "$(dirname "$0")/../lib.sh"
study; pulseStudy > ../log.s1 2>&1 & p=$!; waitFor 240 bash -c "ls postProcessing/pulseStudy/points/*/case/log.cellBlastFoam" && echo "   the point's solver started"
kill -KILL $p; wait $p 2>/dev/null; echo "   left running: $(inDir $W | cut -c1-200)"
tryt 60 "resumed at once" pulseStudy; echo "   points: $(ls postProcessing/pulseStudy/points/* 2>/dev/null | tr '\n' ' ')"; echo "   still running: $(inDir $W | cut -c1-200)"; killIn $W; sleep 1

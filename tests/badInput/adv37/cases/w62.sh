#!/bin/bash
# w62: pulseStudy: a one-point study SIGKILLed 6 s in (its point's Allrun/solver may live on as orphans), then the same command again at once: two runs in the point's case? the series equal to a clean study's?
. "$(dirname "$0")/../lib.sh"
study; cp -r . ../clean; pulseStudy -case . > log.1 2>&1 & p=$!; sleep 6; kill -KILL $p; wait $p 2>/dev/null; echo "pulseStudy killed; still running in the study: $(inDir $W/study)"
run 240 pulseStudy -case . > log.2 2>&1; fatal log.2 4; tail -1 log.2 | cut -c1-200; ls postProcessing/pulseStudy/points/*/ | tr '\n' ' '; echo; sleep 1; echo "left running: $(inDir $W/study)"
(cd ../clean && pulseStudy -case . > log.c 2>&1; echo "clean study rc=$?"); /usr/bin/python3 -c "
import json,glob; a=json.load(open(glob.glob('postProcessing/pulseStudy/points/*/result.json')[0])); b=json.load(open(glob.glob('../clean/postProcessing/pulseStudy/points/*/result.json')[0]))
print('series equal to the clean study:', a['series']==b['series'])"

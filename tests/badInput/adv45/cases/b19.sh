#!/bin/bash
# b19 (class 4, pulseStudy with unicode and a space in the base case's path and the study's): (a) baseCase "$W/bäse/preview" (UTF-8): the point runs or is refused naming the path; (b) baseCase "$W/b c/preview": refused naming baseCase before anything runs; (c) the study itself in "$W/stüdy ü": runs or refused naming the case path; never a traceback?
. "$(dirname "$0")/../lib.sh"
mkdir -p "$W/bäse" "$W/b c"; cp -r "$ROOT/tutorials/blast/axisymmetricPreview" "$W/bäse/preview"; cp -r "$W/bäse/preview" "$W/b c/preview"
study; cp system/pulseStudyDict ../dict.orig
sed -i "s|^baseCase .*|baseCase        \"$W/b c/preview\";|" system/pulseStudyDict; timeout -s KILL 60 pulseStudy -case . > ../log.b 2>&1; echo "(b) space: rc=$? | $(grep -a -m1 -i 'error\|refus\|Traceback\|done' ../log.b | cut -c1-220)"; rm -rf postProcessing
sed -i "s|^baseCase .*|baseCase        \"$W/bäse/preview\";|" system/pulseStudyDict; run 250 pulseStudy -case . > ../log.a 2>&1; echo "(a) unicode: $(grep -a -m2 -i 'error\|refus\|Traceback\|done' ../log.a | cut -c1-220 | tr '\n' '|')"
cp -r $W/study "$W/stüdy ü"; cd "$W/stüdy ü"; rm -rf postProcessing; cp ../dict.orig system/pulseStudyDict; timeout -s KILL 60 pulseStudy -case . > ../log.c 2>&1; echo "(c) study folder with a space: rc=$? | $(grep -a -m1 -i 'error\|refus\|Traceback\|done' ../log.c | cut -c1-220)"

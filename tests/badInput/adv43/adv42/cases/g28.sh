#!/bin/bash
# g28 (class 6, the indentation's output and step count): the smoke indentation (about 2 s of loading table) with (a) fieldWriteInterval 1e-7 s (about 2e7 field writes of solid.h5), (b) maxDepthIncrement 1e-14 m (about 1e8 steps), (c) holdDeltaT0 1e-12 with holdGrowth 1.0000001 (a hold of 1 s in ~1e12 steps): refused with an estimate before anything runs, or run (then: how fast do the outputs grow; killed at 40 s)?
. "$(dirname "$0")/../lib.sh"
ind; cp constant/indenterProperties $W/ip.orig; cp system/controlDict $W/cd.orig
t() { cellIndentationFoam > $W/t.log 2>&1 & local p=$!; waitFor 40 bash -c "! kill -0 $p"; local alive=$(kill -0 $p 2>/dev/null && echo yes); kill -KILL $p 2>/dev/null; wait $p; local rc=$?
  echo "$1: $([ -n "$alive" ] && echo "still running at 40 s (killed)" || echo "rc $rc") | $(grep -a -m1 -A2 'FATAL\|rror' $W/t.log | grep -av '^ *$' | tr '\n' ' ' | cut -c1-240)"; echo "   outputs: $(du -sh postProcessing 2>/dev/null | cut -f1) in postProcessing; force rows $(grep -vc '^#' postProcessing/indentation/force.dat 2>/dev/null); solid.h5 steps $(h5steps postProcessing/indentation/solid.h5 2>/dev/null)"; rm -rf postProcessing; }
sete system/controlDict fieldWriteInterval 1e-7; t "(a) fieldWriteInterval 1e-7"; cp $W/cd.orig system/controlDict
sete constant/indenterProperties maxDepthIncrement 1e-14; sete constant/indenterProperties tolerance 1e-16; t "(b) maxDepthIncrement 1e-14 (tolerance 1e-16)"; cp $W/ip.orig constant/indenterProperties
sete constant/indenterProperties holdDeltaT0 1e-12; sete constant/indenterProperties holdGrowth 1.0000001; t "(c) holdDeltaT0 1e-12, holdGrowth 1.0000001"; cp $W/ip.orig constant/indenterProperties

#!/bin/bash
# d37 (class 4, protocol rows odd, one at a time, cellIndentationFoam, 40 s): kind laod; a row of 5 items; hold of -1 s; load amount 1e-400; rate -0; rate 0 on a load; an empty protocol (); a label with a space "\"A 1\""; amount 0x1p-22: each refused before the first step naming the row and entry.
. "$(dirname "$0")/../lib.sh"
ind; cp constant/indenterProperties ../ip
for r in "(A laod 0.3e-6 0.3e-6)" "(A load 0.3e-6 0.3e-6 1)" "(A hold 0 -1)" "(A load 0.3e-6 1e-400)" "(A load -0 0.3e-6)" "(A load 0 0.3e-6)" "" "(\"A 1\" load 0.3e-6 0.3e-6)" "(A load 0.3e-6 0x1p-22)"; do cp ../ip constant/indenterProperties
  R="$r" python3 - constant/indenterProperties <<P
import os,re,sys; p=sys.argv[1]; t=open(p).read(); i=t.index("protocol"); a=t.index("(", i); j=t.index(");", i)
open(p,"w").write(t[:a]+"(\n    "+os.environ["R"]+"\n"+t[j:])
P
  tryt 40 "[$r]" cellIndentationFoam; [ -d postProcessing ] && echo "      (ran: $(ls postProcessing/indentation | tr "\n" " "))"; rm -rf postProcessing; done

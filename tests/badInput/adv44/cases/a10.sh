#!/bin/bash
# a10 (class 2, 52916a0's refusal in DEPTH): a finished one-point study; the user's files in the study's base copy postProcessing/pulseStudy/base/: (a) constant/notes.md (a sub-folder), (b) a hidden .notes, (c) a folder of their own myPlots/a.txt, (d) a symbolic link base/data -> $W/mine (their data outside); ./Allrun again (nothing to run): refused naming each, nothing removed (and the link's target untouched)?
. "$(dirname "$0")/../lib.sh"
study; run 250 ./Allrun > ../log.s1 2>&1; echo "   first: $(grep -a -i -m2 'error\|done' ../log.s1 | cut -c1-140 | tr '\n' '|')"; B=postProcessing/pulseStudy/base
mkdir -p $W/mine $B/myPlots; echo "a10 mine outside" > $W/mine/x.txt; echo "a10 constant notes" > $B/constant/notes.md; echo "a10 hidden notes" > $B/.notes; echo "a10 plot data" > $B/myPlots/a.txt; ln -s $W/mine $B/data
run 250 ./Allrun > ../log.s2 2>&1; echo "   again: $(grep -a -i -m3 'error\|refus\|kept\|holds' ../log.s2 | cut -c1-400 | tr '\n' '|')"; where "a10 constant notes" "a10 hidden notes" "a10 plot data" "a10 mine outside"; echo "   link: $(ls -l $B/data 2>&1 | awk '{print $NF}')"

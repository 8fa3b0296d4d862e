#!/bin/bash
# x65: blast preview Allrun options at their range edges never tried: -pulse 0.9 (max) with -endTime 2e-9, -solidSubcycles 1e9, -shearViscosity 0.9999999, -writeInterval 1e-3 (above the run), -amplitude 1e9 (max): each runs sensibly or is refused naming the option and range?
. "$(dirname "$0")/../lib.sh"
prev; cp -r . ../orig; S="-h 0.25e-6 -far 2e-6 -dz 0.25e-6 -cell 0.5e-6 -Z 20e-6 -endTime 2e-9 -noPlots -noVTK"
for o in "-pulse 0.9" "-solidSubcycles 1e9" "-shearViscosity 0.9999999" "-writeInterval 1e-3" "-amplitude 1e9"; do rm -rf $W/c; cp -r ../orig $W/c; cd $W/c; run 150 ./Allrun $S $o > ../log.o 2>&1 | tr '\n' ' '; echo " $o: $(grep -a -i -m2 'error\|FATAL\|invalid\|refus' ../log.o | tr '\n' ' ' | cut -c1-250) | last: $(tail -1 ../log.o | cut -c1-120) | times $(ls -d [1-9]* 2>/dev/null | tr '\n' ' ')"; done

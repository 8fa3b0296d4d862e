#!/bin/bash
# f04 (class 1/5, a results folder renamed: the time directory 2e-09 renamed 2.5e-09 by the user, its files and marker untouched), restart latestTime to 3e-9: refused naming 2.5e-09 (its contents are of 2e-09); never continued from "2.5e-09" (the time line shifted by 0.5 ns). (b) renamed back: the plain restart continues.
. "$(dirname "$0")/../lib.sh"
bd; rs; mv 2e-09 2.5e-09; sums > ../s0
tryt 240 "(a) 2e-09 renamed 2.5e-09" cellBlastFoam; cont; echo "   changed: $(changed ../s0)"; after
rm -rf 3e-09; mv 2.5e-09 2e-09 2>/dev/null; tryt 240 "(b) renamed back" cellBlastFoam; cont; after

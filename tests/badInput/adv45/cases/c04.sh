#!/bin/bash
# c04 (phase 2, class 4, sweepCase's case-path check; from fix19b-fixed.md's b05 line only): sweepCase -case with (a) a single quote in the path, (b) a tab, (c) a trailing slash on a good path, (d) a path through a symbolic link whose NAME holds a space (the real folder has none): (a), (b) refused before anything is copied naming the path; (c) runs; (d) runs or is refused naming the path, nothing left beside either?
. "$(dirname "$0")/../lib.sh"
ind; cd $W; mkdir -p "q'x" "$(printf 't\tx')"; cp -r ind "q'x/ind"; cp -r ind "$(printf 't\tx')/ind"; ln -s $W/ind "$W/l nk"
for c in "$W/q'x/ind" "$(printf '%s/t\tx/ind' $W)" "$W/ind/" "$W/l nk"; do tryf "[$c]" sweepCase -case "$c" -entry constant/indenterProperties/maxDepthIncrement -values "0.1e-6" -run cellIndentationFoam -output "F=postProcessing/indentation/peaks.dat:-1:force"; grep -a '^|' $W/try.log | sed -n 3p; done
echo "   W: $(ls -a $W | tr '\n' ' ')"; echo "   q'x: $(ls -a "$W/q'x" | tr '\n' ' ')"

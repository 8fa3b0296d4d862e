#!/bin/bash
# g24 (class 3, the main job twice at once) in a copy of the project tree (tutorials copied, the rest linked) two 'tutorials/Allrun' started 2 s apart, both killed (their process groups) after 150 s: the second refused at once naming the first (or waiting), never both working in one tutorial folder at the same moment (sampled every 0.5 s) and never one Allclean'ing the other's results.
. "$(dirname "$0")/../lib.sh"
mkdir $W/root; for f in $ROOT/*; do [ "${f##*/}" = tutorials ] || ln -s $f $W/root/; done; cp -r $ROOT/tutorials $W/root/tutorials; T=$W/root/tutorials
set -m; $T/Allrun > $W/m1.log 2>&1 & p1=$!; sleep 2; $T/Allrun > $W/m2.log 2>&1 & p2=$!; set +m
both=0; for i in $(seq 1 300); do a=$(for q in $(pgrep -g $p1); do readlink /proc/$q/cwd; done 2>/dev/null | grep -o 'tutorials/[^/]*/[^/]*' | sort -u); b=$(for q in $(pgrep -g $p2); do readlink /proc/$q/cwd; done 2>/dev/null | grep -o 'tutorials/[^/]*/[^/]*' | sort -u); c=$(comm -12 <(echo "$a") <(echo "$b") | grep .); [ -n "$c" ] && { both=$((both+1)); [ $both -le 3 ] && echo "   both in: $c"; }; sleep 0.5; done
kill -KILL -- -$p1 -$p2 2>/dev/null; wait; echo "   samples with both in one folder: $both"
echo "   first: $(head -c 2000 $W/m1.log | grep -a -i 'refus\|in use\|error\|==' | head -3 | cut -c1-160 | tr '\n' '|')"; echo "   second: $(grep -a -i 'refus\|in use\|error\|==' $W/m2.log | head -3 | cut -c1-200 | tr '\n' '|')"

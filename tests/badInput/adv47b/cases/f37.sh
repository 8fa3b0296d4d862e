#!/bin/bash
# f37 (environment, a case path with control characters other than those documented): the smoke indentation in a folder whose name holds a carriage return (a\rb), a vertical tab (a\vb), a form feed (a\fb), an escape (a\x1bb): cellIndentationFoam -case PATH: each runs there or refuses naming the path; never results written into another folder (a name with the character dropped: ab).
. "$(dirname "$0")/../lib.sh"
for c in '\r' '\v' '\f' '\x1b'; do d="$W/a$(printf "$c")b"; mkdir -p "$d"; cp -r $ADV/indBase/{system,constant} "$d/"; cd $W
  tryt 120 "path with $c" cellIndentationFoam -case "$d"; echo "   force.dat files: $(find $W -name force.dat | cat -A | tr '\n' ' ')"; rm -rf "$d" $W/ab; done

#!/bin/bash
# x08: blast preview Allrun (small options, 2 ns) run through a symbolic link whose NAME holds a space ("my case" -> c): the physical path has none; runs to its end or is refused clearly? Then the reverse: the real folder 'with space' reached through a link 'nospace'
. "$(dirname "$0")/../lib.sh"
prev; cd $W; ln -s $W/c "$W/my case"; run 200 "$W/my case/Allrun" $PREV -endTime 2e-9 > log.a 2>&1; tail -2 log.a | cut -c1-250; ls -d c/[1-9]* 2>/dev/null | tr '\n' ' '; echo
cp -r $ROOT/tutorials/blast/axisymmetricPreview "$W/with space"; ln -s "$W/with space" $W/nospace; run 60 $W/nospace/Allrun $PREV -endTime 2e-9 > log.b 2>&1; tail -3 log.b | cut -c1-300; ls "$W/with space" | tr '\n' ' '

#!/bin/bash
# An output of cellIndentationFoam lost during the run (issue 19, class
# 4): force.dat removed while the run goes on (an Allclean, a user's rm).
# The next checkpoint used to end the run in std::terminate (an uncaught
# std::filesystem error, exit 134, "terminate called"); now the run stops
# with a FatalError naming the file, exit 1, no crash trace; also without
# checkpoints (checkpointInterval 0), where it was never caught (exit 0).
set -euo pipefail
. "$(dirname "$0")/../lib/restartTools.sh"
. "$(dirname "$0")/../lib/checks.sh"

mkdir "$work/base"; cd "$work/base"
cp -r "$root/tutorials/indentation/averageCell"/{system,constant} .
gmsh -2 -setnumber D 16.8 -setnumber H 7.9 -setnumber h 1.6 \
    -setnumber hc 0.8 -setnumber nm 24 \
    "$root/tests/lib/cellFallback.geo" \
    -o constant/cell.msh > log.gmsh 2>&1
/usr/bin/python3 "$root/tests/lib/setProtocol.py" constant/indenterProperties \
    --smoke
out=postProcessing/indentation

# lost NAME: a copy of the base case, force.dat removed as soon as it
# exists (without checkpoints it holds nothing on disk until the end:
# the lines wait in the stream's buffer); exit 1 naming it, no crash trace
lost()
{
    cp -r "$work/base" "$work/$1"; cd "$work/$1"
    local status=0
    cellIndentationFoam > log.run 2>&1 &
    local pid=$!
    until [ -e $out/force.dat ] || ! kill -0 $pid 2> /dev/null; do sleep 0.01; done
    rm -f $out/force.dat
    wait $pid || status=$?
    check "$1: force.dat removed during the run: exit 1, the file named, no crash" \
        "[ $status -eq 1 ] && grep -q 'cannot write .*/$out/force.dat: No such file' log.run \
         && ! grep -Eq 'terminate called|Aborted' log.run"
    [ $status -eq 1 ] || tail -4 log.run
}
lost checkpoints
# Without checkpoints (checkpointInterval 0) the outputs were checked
# nowhere: the run ended with exit 0 and force.dat lost; now every step
printf '\ncheckpointInterval 0;\n' >> "$work/base/system/controlDict"
lost noCheckpoints
exit $fail

#!/bin/bash
# runPreview.sh dir [Allrun options]: a copy of tutorials/blast/
# axisymmetricPreview (inputs only) in dir/axisymmetricPreview, run there
# with the given Allrun options
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../../etc/bashrc"
src=$here/../../tutorials/blast
# DIR first, not an option (adv53 l18: "-d" gave mkdir's "invalid option"
# and left a folder "-d"; a folder of that name: ./-d)
case "${1:-}" in
    ""|-*)
        echo "runPreview.sh: error: the first argument is the output folder" \
            "DIR (given: '${1:-}'; a folder whose name begins with '-':" \
            "./NAME). Usage: runPreview.sh DIR [Allrun options]" >&2
        exit 1 ;;
esac
dir=$1; shift
# DIR new, empty or an earlier output of this script (adv51 n01: a user's
# folder given as DIR was removed)
. "$here/../../etc/scratchFolder"
scratchFolder runPreview.sh "$dir" "axisymmetricPreview/@case"
mkdir -p "$dir/axisymmetricPreview"
for f in 0.orig constant system Allrun
do
    cp -r "$src/axisymmetricPreview/$f" "$dir/axisymmetricPreview/"
done
cd "$dir/axisymmetricPreview"
rm -rf constant/cell.msh constant/polyMesh system/blockMeshDict
./Allrun "$@"

#!/bin/bash
# rowsOnBuild.sh PROJECT REGEX: the exit code of each corpus row whose name
# matches REGEX and whose base case is 'preview', run with the build of
# another worktree PROJECT (its etc/bashrc), e.g. main before a fix:
#   bash tests/badInput/rowsOnBuild.sh /work/main '^adv37'
# (a row that a fix adds must exit 0 - or at least not refuse as the row
# requires - on the build without the fix). The edit runs in a fresh copy
# of PROJECT's tutorials/blast/axisymmetricPreview, as runCorpus.sh's
# preview base. Not run by ctest (it needs the other build).
set -uo pipefail
project=$1 select=$2
corpus=$(cd "$(dirname "$0")" && pwd)/corpus
. "$project/etc/bashrc"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
field() { awk -F ' [|] ' -v i="$2" '{ gsub(/^ +| +$/, "", $i); print $i }' <<< "$1"; }
grep -v '^[[:space:]]*\(#\|$\)' "$corpus" | while IFS= read -r row
do
    name=$(field "$row" 1); base=$(field "$row" 2)
    app=$(field "$row" 3); edit=$(field "$row" 6)
    grep -Eq "$select" <<< "$name" && [ "$base" = preview ] || continue
    c=$work/$name
    mkdir -p "$c"
    cp -r "$project"/tutorials/blast/axisymmetricPreview/{0.orig,system,constant,Allrun,Allclean} "$c"/
    (cd "$c" && ./Allclean > /dev/null && eval "$edit") < /dev/null > "$c/log.edit" 2>&1 \
        || { echo "$name: the edit failed"; continue; }
    (cd "$c" && eval "timeout -k 5 120 $app") < /dev/null > "$c/log.app" 2>&1
    echo "$name: exit $? with $project"
done

#!/bin/bash
# The tutorials leave the tree as they found it: every tutorial is run with
# its smoke options in a scratch git repository holding a copy of
# tutorials/ and the project's .gitignore (the real tree is not touched, and
# the indentation tables can be shortened in the copy's first commit).
# Asserted per case: without the project environment, Allrun and Allclean
# stop at once with "source <project>/etc/bashrc first"; after ./Allrun,
# `git status --porcelain` is empty (no tracked file edited, every output
# ignored); after ./Allclean, also with --ignored (the pristine state). The calibration tutorial (minutes of
# CPU) is left out.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
. "$root/etc/bashrc"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
repo=$work/repo
mkdir -p "$repo"
cp -r "$root/tutorials" "$root/.gitignore" "$repo/"
cd "$repo"
# every tutorial: a folder with an Allrun, one or two levels down
# (tutorials/paper, tutorials/<scene>/<case>)
cases=$(for a in tutorials/*/Allrun tutorials/*/*/Allrun
        do [ -f "$a" ] && echo "${a%Allrun}"; done)
for c in $cases
do
    [ -x "$c/Allclean" ] && (cd "$c" && ./Allclean > /dev/null 2>&1)
done
# The indentation smoke table (tests/indentation/smokeIndentation.sh)
for c in tutorials/indentation/averageCell tutorials/indentation/validationCell
do
    /usr/bin/python3 "$root/tests/lib/setProtocol.py" \
        "$c/constant/indenterProperties" --smoke
done
git init -q
git add -A
git -c user.name=test -c user.email=test@localhost commit -q -m pristine

fails=0
check()     # case, what, git status options
{
    local out
    out=$(git status --porcelain ${3:-} -- "$1")
    if [ -n "$out" ]
    then
        echo "FAIL $1: $2:"; echo "$out" | head -20; fails=$((fails + 1))
    else
        echo "ok   $1: $2"
    fi
}
run()       # case [Allrun options]
{
    local c=$1; shift
    if (cd "$c" && ./Allrun "$@" > log.cleanTree 2>&1)
    then
        check "$c" "git status clean after Allrun $*"
    else
        echo "FAIL $c: Allrun $* failed:"; tail -20 "$c/log.cleanTree"
        fails=$((fails + 1))
    fi
    (cd "$c" && ./Allclean > /dev/null 2>&1)
    check "$c" "pristine after Allclean" --ignored
}

# Without the project environment every Allrun and Allclean stops at once
# with the message, touching nothing (tutorials/paper only so: its runs
# are the other tutorials')
for c in $cases
do
    for script in Allrun Allclean
    do
        out=$(cd "$c" && env -i HOME="$HOME" PATH=/usr/bin:/bin \
            bash "./$script" 2>&1) && status=0 || status=$?
        if [ "$status" -ne 0 ] \
            && [ "$out" = "$script: source <project>/etc/bashrc first" ]
        then
            check "${c%/}" "$script without the environment: '$out'" --ignored
        else
            echo "FAIL ${c%/}: $script without the environment: exit" \
                "$status, '$out'"
            fails=$((fails + 1))
        fi
    done
done

for c in tutorials/verification/*/
do
    run "${c%/}"
done
run tutorials/blast/axisymmetricPreview -h 0.25e-6 -far 2e-6 -cell 0.5e-6 \
    -Z 30e-6 -endTime 2e-9
# shortened (constant/inflowWave, controlDict.allrun), not run
run tutorials/blast/axisymmetricPreview -h 0.25e-6 -far 2e-6 -cell 0.5e-6 \
    -Z 30e-6 -endTime 2e-9 -inflow 20e-6 -noRun
run tutorials/blast/quarter3D -box 30e-6 -h 0.6e-6 -far 2e-6 -growth 5e-6 \
    -cell 1.4e-6 -endTime 2e-9
# decomposed (system/decomposeParDict.allrun, processor*), not run: 2 ns
# has no write time to reconstruct
run tutorials/blast/quarter3D -box 30e-6 -h 0.6e-6 -far 2e-6 -growth 5e-6 \
    -cell 1.4e-6 -np 2 -noRun
for c in tutorials/indentation/averageCell tutorials/indentation/validationCell
do
    run "$c"
done
[ "$fails" -eq 0 ] || { echo "cleanTree: $fails failures"; exit 1; }
echo "cleanTree: every tutorial leaves the tree clean"

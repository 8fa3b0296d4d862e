#!/bin/bash
#------------------------------------------------------------------------------
# runSuite.sh SUITE: run one GoogleTest suite of foamUnitTests in the
# environment of etc/bashrc (ctest: CMakeLists.txt). Fails if the executable
# is missing (not built by ./Allwmake) or has no suite SUITE.
# runSuite.sh --check SUITE...: fails unless the executable's suites are
# exactly these (a new suite must be registered in CMakeLists.txt).
#------------------------------------------------------------------------------
set -uo pipefail
dir=$(cd "$(dirname "$0")" && pwd)
. "$dir/../../etc/bashrc"
exe=$FOAM_USER_APPBIN/foamUnitTests
if [ ! -x "$exe" ]
then
    echo "FAIL: $exe is missing: run ./Allwmake" >&2
    exit 1
fi
suites=$("$exe" --gtest_list_tests | sed -n 's/^\([A-Za-z0-9_]*\)\.$/\1/p' \
    | sort)
if [ -z "$suites" ]
then
    echo "FAIL: $exe --gtest_list_tests lists no suite" >&2
    exit 1
fi
if [ "${1:-}" = --check ]
then
    shift
    expected=$(printf '%s\n' "$@" | sort)
    if [ "$suites" != "$expected" ]
    then
        echo "FAIL: suites of $exe:" $suites "; registered in" \
            "tests/foamUnit/CMakeLists.txt:" $expected >&2
        exit 1
    fi
    echo "ok: suites" $suites
    exit 0
fi
if ! grep -qx -- "${1:-}" <<< "$suites"
then
    echo "FAIL: no suite '${1:-}' in $exe (suites:" $suites")" >&2
    exit 1
fi
exec "$exe" --gtest_filter="$1.*"

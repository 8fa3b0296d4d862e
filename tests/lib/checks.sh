# Shared by the shell tests that list checks (tests/fsi/caseLock.sh,
# tests/verification/resultGuard.sh, restartInputs.sh). Sourced, it sets
# fail=0 and defines:
#   check WHAT CONDITION   evaluates the shell code CONDITION, prints
#                          "ok   WHAT" or "FAIL WHAT" (then fail=1);
#                          the script ends with exit $fail
#   caseSums [PATTERN]     md5 of every file below the current directory
#                          whose name does not match PATTERN (default
#                          log.*), sorted: equal output, unchanged files
fail=0
check() { if eval "$2"; then echo "ok   $1"; else echo "FAIL $1"; fail=1; fi; }
caseSums()
{
    find . -type f ! -name "${1:-log.*}" -print0 | sort -z | xargs -0 md5sum
}

#!/bin/bash
#------------------------------------------------------------------------------
# bench/ciTime/corpusHarness.sh OLD NEW OUT [EVERY]: the CPU of the
# bad-input corpus' harness itself (runCorpus.sh without the applications),
# two checkouts side by side. Writes a copy of the corpus with every EVERY-th
# row (default 4) whose application is 'false' and whose edit is 'true'
# (names, bases and regexes as committed), and runs OLD's and NEW's
# runCorpus.sh on it (each in a scratch tree under OUT linking the
# checkout's etc, tutorials, tests/lib, tests/verification and tests/fsi) at the same
# time, nice -n 10: every row then fails at 'the message does not name the
# file' after the same steps as a real row (copy of the base, edit, md5 of
# the case, the run, the message's checks). Prints wall and CPU
# (/usr/bin/time) of each and the load.
#------------------------------------------------------------------------------
set -uo pipefail
[ $# -ge 3 ] || { echo "usage: $0 OLD NEW OUT [EVERY]" >&2; exit 1; }
old=$(cd "$1" && pwd) new=$(cd "$2" && pwd) out=$3 every=${4:-4}
# OUT new, empty or an earlier output of this script, locked for the run
# (adv53 u06: `rm -rf "$out"` removed a user's OUT/notes.txt)
. "$(cd "$(dirname "$0")/../.." && pwd)/etc/scratchFolder"
scratchFolder corpusHarness.sh "$out" old new old.log new.log old.time new.time
for s in old new
do
    src=${!s} t=$out/$s
    mkdir -p "$t/tests/badInput"
    ln -s "$src/etc" "$t/etc"; ln -s "$src/tutorials" "$t/tutorials"
    ln -s "$src/tests/lib" "$t/tests/lib"
    ln -s "$src/tests/verification" "$t/tests/verification"
    ln -s "$src/tests/fsi" "$t/tests/fsi"
    cp "$src/tests/badInput/runCorpus.sh" "$src/tests/badInput/cellMeshDict" \
        "$t/tests/badInput/"
    grep -v '^[[:space:]]*\(#\|$\)' "$src/tests/badInput/corpus" \
        | awk -F ' [|] ' -v OFS=' | ' -v e="$every" \
            '(NR - 1) % e == 0 { $3 = "false"; $6 = "true"; print }' \
        > "$t/tests/badInput/corpus"
done
echo "corpusHarness: $(wc -l < "$out/new/tests/badInput/corpus") rows (every $every-th)," \
    "start $(date -u +%H:%M:%S) UTC, load $(cut -d' ' -f1-3 /proc/loadavg)"
for s in old new
do
    ( src=${!s}; . "$src/etc/bashrc"
      export MAKE_SOLID_RESULTS=$src/build/bin/makeSolidResults
      /usr/bin/time -f "$s %e %U %S" -o "$out/$s.time" nice -n 10 \
          bash "$out/$s/tests/badInput/runCorpus.sh" > "$out/$s.log" 2>&1 ) &
done
wait
echo "corpusHarness: end $(date -u +%H:%M:%S) UTC, load $(cut -d' ' -f1-3 /proc/loadavg)"
cat "$out/old.time" "$out/new.time" | awk '/^(old|new) / { printf "  %s: wall %.1f s, CPU %.1f s\n", $1, $2, $3 + $4 }'
for s in old new
do
    echo "  $s: $(tail -1 "$out/$s.log"); $(grep -c 'does not name the file' "$out/$s.log") rows failed at the file check"
done

# lib.sh (adv36): adv35's lib.sh (base cases, ind/indDone/blast/blastDone/sod/sodDone, setd, sums) plus:
#   blastEnd END WI   the blast case's end time and write interval (system/controlDict.allrun, read last)
#   contents          md5 of every result file's content (names ignored; system/ and constant/ left out), hidden files included, sorted
#   lost BEFORE       prints each content of file BEFORE (from `contents`) found nowhere in the case now
. "$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)/../adv35/lib.sh"
blastEnd() { printf 'endTime %s;\nwriteInterval %s;\n' "$1" "$2" > system/controlDict.allrun; }
contents() { find . -type f ! -path './system/*' ! -path './constant/*' ! -name 'log.*' ! -name '.runLock' ! -name 'before*' -print0 | xargs -0 md5sum | awk '{print $1}' | sort -u; }
lost() { contents > /tmp/.adv36now.$$; comm -23 "$1" /tmp/.adv36now.$$; rm -f /tmp/.adv36now.$$; }

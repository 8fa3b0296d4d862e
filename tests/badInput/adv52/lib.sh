# lib.sh (adv52): adv51's lib.sh (and through it every helper of adv35-adv51: bd, idn, ik, q, pbd, sbd, blast, short,
# latest, rs, tryt, msg, sete, subset, fsiSet, fset, sig, hdr0/hdr, inDir, killIn, killAll, pwd0, prj, iw ...) read
# unchanged from its folder. runOne.sh's ADV=<prefix>adv52 is mapped to <prefix>adv51, which adv51's lib.sh maps on to
# <prefix>adv50b ... <prefix>adv47b: every base lies there (prebuild.sh). At the case's exit $W is removed.
# Mine:
#   md5all        md5 of every file under the current folder but logs (one line per file, sorted) -> stdout
#   same0 / same1 md5all kept in $W/same0, then compared: "files kept" or the files that changed/appeared/vanished
#   mark F        a user's file F (text "users data") created, so that its loss is seen: "F kept" / "F LOST" by kept_ F
ADV=${ADV:-/tmp/adv52-adv52}; ADV=${ADV%adv52}adv51
here52_=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
. "$here52_/../adv51/lib.sh"
md5all() { find . -type f ! -name 'log*' ! -name '.runLock' -print0 2>/dev/null | sort -z | xargs -0 -r md5sum; }
same0() { md5all > $W/same0; }
same1() { md5all > $W/same1; if cmp -s $W/same0 $W/same1; then echo "   files kept ($(wc -l < $W/same0) files)"; else echo "   FILES CHANGED: $(diff $W/same0 $W/same1 | grep '^[<>]' | awk '{print $1, $3}' | sort -u -k2 | tr '\n' ' ' | cut -c1-600)"; fi; }
mark() { mkdir -p "$(dirname "$1")"; echo "users data $1" > "$1"; }
kept_() { if [ "$(cat "$1" 2>/dev/null)" = "users data $1" ]; then echo "   $1 kept"; else echo "   $1 LOST"; fi; }

# lib.sh (adv45): adv44's lib.sh (tests/badInput/adv44: all helpers of adv35-adv44: ind/indDone, indKilled, blast/blastDone,
# pblast/pblastDone, iblast/iEnd/IW, blastEnd, latest, restart0, sums, changed, nochange, kept, where, tryf, try, run, fatal,
# waitFor, sameSeries, study, setStudy, cal, prev/PREV, flip, h5same, h5steps, xmfsteps, nul, marks, lockOf, ...) with ADV
# defaulting to /tmp/adv45-adv45, plus:
#   ro DIR           DIR made read-only by a read-only bind mount of itself (we run as root: chmod does not stop root);
#                    undone at the case's exit (unmounts every mount under $W)
#   tiny SIZE        a tmpfs of SIZE mounted at $W/fs (a full disk), unmounted at the case's exit
#   odd              the odd numbers of this pass: beyond a double, below it, hex, denormals, negative zero
ADV=${ADV:-/tmp/adv45-adv45}
. "$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)/../adv44/lib.sh"
unmountAll() { cd / 2>/dev/null; for m in $(awk -v w="$W" 'index($2, w) == 1 {print $2}' /proc/mounts | sort -r); do umount -l "$m" 2>/dev/null; done; }
trap unmountAll EXIT
ro() { mount --bind "$1" "$1" && mount -o remount,ro,bind "$1" "$1" || echo "ro: could not mount $1 read-only"; }
tiny() { mkdir -p $W/fs; mount -t tmpfs -o size=$1 tmpfs $W/fs || echo "tiny: could not mount"; }
ODD="1e308 1e-400 -0 0x1p-20 4.9e-324 1e400"

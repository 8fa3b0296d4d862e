#!/bin/bash
# w27: blast: postProcessing/ is a symlink to another finished case's postProcessing/, restart to 3 ns: the other case's logs written through the link?
. "$(dirname "$0")/../lib.sh"
blastDone; latest; cd ..; cp -r blast other; (cd other && find postProcessing -type f | sort | xargs md5sum) > o.md5; cd blast; rm -rf postProcessing; ln -s ../other/postProcessing postProcessing; blastEnd 3e-9 1e-9
run 120 cellBlastFoam > log.r 2>&1; fatal log.r 4; tail -1 log.r; (cd ../other && md5sum -c --quiet ../o.md5) && echo "other case's logs unchanged"

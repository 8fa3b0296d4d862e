#!/bin/bash
# w99: solidToFoam on solid.h5 copies each with ONE bit flipped at 1/10 ... 9/10 of the file: every damage that changes the converted fields refused (checksums), none converted silently?
. "$(dirname "$0")/../lib.sh"
blastDone; rm -rf ../orig; cp -r . ../orig; (cd ../orig && solidToFoam solid/solid.h5 > log.s2f 2>&1; echo "clean conversion rc=$?")
conv() { find constant/solid [0-9]*/solid -type f 2>/dev/null | sort | xargs md5sum 2>/dev/null | md5sum | cut -c1-8; }; ref=$(cd ../orig && conv); n=$(stat -c %s solid/solid.h5)
for k in 1 2 3 4 5 6 7 8 9; do rm -rf ../k; cp -r . ../k; cd ../k; off=$((n*k/10)); /usr/bin/python3 -c "
f=open('solid/solid.h5','r+b'); f.seek($off); b=f.read(1); f.seek($off); f.write(bytes([b[0]^0x04])); f.close()"
  solidToFoam solid/solid.h5 > log.s2f 2>&1; rc=$?; c=$(conv); if [ $rc -ne 0 ]; then v="refused: $(grep -a -m1 -A1 FATAL log.s2f | tail -1 | cut -c1-150)"; elif [ "$c" = "$ref" ]; then v="converted, output equal to the clean one"; else v="CONVERTED, OUTPUT DIFFERS from the clean one"; fi; echo "flip at $off: rc=$rc $v"; cd - > /dev/null; done

#!/bin/bash
# b26 (class 4+6, calibrateCell's curve target of odd kinds): targets { curve { file "<f>"; sigma 0.02e-9; } } with <f> a FIFO, a link to /dev/zero (endless), /dev/null (empty), a directory, 3 MB of random bytes, a CSV with CRLF line ends and ';' separators: each refused within seconds naming the file; no hang, no traceback?
. "$(dirname "$0")/../lib.sh"
cal; cp system/calibrationDict ../dict.orig; mkfifo ../fifo; ln -s /dev/zero ../zero; mkdir -p ../adir; head -c 3000000 /dev/urandom > ../rand; printf 't [s];F [N]\r\n0;0\r\n1;1e-10\r\n' > ../semi.csv
for f in $W/fifo $W/zero /dev/null $W/adir $W/rand $W/semi.csv; do cp ../dict.orig system/calibrationDict; sed -i "s|F_E { peak endE; value 1.67e-9; }|curve { file \"$f\"; sigma 0.02e-9; }|" system/calibrationDict
  timeout -s KILL 60 calibrateCell -case . > ../log.c 2>&1; echo "curve $f: rc=$? | $(grep -a -m1 -i 'error\|refus\|Traceback\|evaluation' ../log.c | cut -c1-220)"; done

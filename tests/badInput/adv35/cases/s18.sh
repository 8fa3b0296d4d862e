#!/bin/bash
# s18: ind: a protocol of 20000 rows (each 1e-9 m load/unload)
. "$(dirname "$0")/../lib.sh"
ind; python3 - <<'P'
import re; f='constant/indenterProperties'; s=open(f).read()
rows = "\n".join("    (C%d %s 10e-6 1e-9)" % (i, "load" if i % 2 == 0 else "unload") for i in range(20000))
s = re.sub(r"protocol\s*\(.*?\n\);", "protocol\n(\n    (A load 0.3e-6 0.3e-6)\n" + rows + "\n);", s, flags=re.S); open(f, 'w').write(s)
P
timeout 120 cellIndentationFoam > log.run 2>&1; rc=$?; grep -A3 "FATAL" log.run | head -4; tail -1 log.run; echo "rc=$rc (124 = still running at 120 s)"

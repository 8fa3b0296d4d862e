#!/bin/bash
# v11: sod: finished; the diaphragm x0 (or the left state) edited in riemannProblemDict; riemannError -latestTime compares with the exact solution of the edited problem?
. "$(dirname "$0")/../lib.sh"
sodDone; riemannError -latestTime > log.re0 2>&1; echo "clean rc=$?"; grep -i "L1\|error" log.re0 | grep -v "^ *$" | head -3
sed -i 's/^x0 .*/x0 0.1;/' system/riemannProblemDict
riemannError -latestTime > log.re 2>&1; rc=$?; grep -A4 "FATAL" log.re | head -6; grep -i "L1\|error" log.re | head -3; echo "rc=$rc"

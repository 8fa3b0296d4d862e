#!/bin/bash
# t48: planeWave -inflow 15e-6 on a case whose top is not planeWaveInflow
. "$(dirname "$0")/../lib.sh"
blastDone; planeWave -inflow 15e-6 -Z 20e-6 > log.pw 2>&1; rc=$?; tail -2 log.pw | cut -c1-250; echo "rc=$rc"; ls constant

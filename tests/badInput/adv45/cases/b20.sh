#!/bin/bash
# b20 (class 4+2, pulseStudy with read-only outputs): (a) postProcessing/pulseStudy a read-only folder (a read-only bind mount: we run as root) before the study: refused naming the folder, no traceback; (b) one point finished, then points/ read-only and a grid value added: the new point fails naming the folder, the finished point's record kept?
. "$(dirname "$0")/../lib.sh"
study; mkdir -p postProcessing/pulseStudy; ro postProcessing/pulseStudy
timeout -s KILL 60 pulseStudy -case . > ../log.a 2>&1; echo "(a) rc=$? | $(grep -a -m2 -i 'error\|refus\|Traceback\|read-only' ../log.a | cut -c1-220 | tr '\n' '|')"; umount postProcessing/pulseStudy; rm -rf postProcessing
run 250 pulseStudy -case . > ../log.b1 2>&1; md5sum postProcessing/pulseStudy/points/*/result.json > ../m; ro postProcessing/pulseStudy/points; setStudy overpressure "(30e6 40e6)"
timeout -s KILL 120 pulseStudy -case . > ../log.b2 2>&1; echo "(b) rc=$? | $(grep -a -m2 -i 'error\|refus\|Traceback\|read-only' ../log.b2 | cut -c1-260 | tr '\n' '|')"; umount postProcessing/pulseStudy/points; echo "   record: $(md5sum -c ../m 2>&1 | awk '{print $2}')"

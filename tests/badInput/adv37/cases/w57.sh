#!/bin/bash
# w57: cellMesh in a case whose constant/ is read-only (bind mount ro): a clear error naming the file, no crash, cell.msh kept?
. "$(dirname "$0")/../lib.sh"
ind; md5sum constant/cell.msh > ../m; mount --bind constant constant && mount -o remount,bind,ro constant; touch constant/x 2>&1 | head -1; try ro cellMesh; grep -a -i "error\|unable\|cannot\|FATAL" $W/try.log | grep -v "relative error" | cut -c1-250; umount constant; md5sum -c ../m > /dev/null && echo "cell.msh kept"

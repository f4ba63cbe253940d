#!/bin/sh
# Re-records NAME.canon from LinuxCNC's rs274 for every NAME.rs274.nc here
# (tests/rs274_reference.rs reads the recorded files; it does not need
# LinuxCNC). Install: apt-get install -y --no-install-recommends linuxcnc-uspace
set -eu
cd "$(dirname "$0")"
command -v rs274 >/dev/null || { echo "rs274 not installed" >&2; exit 2; }
# rs274 keeps its tool table in $HOME/.tool.mmap and truncates it on every
# run: a HOME of this script's own keeps other rs274 runs out of it.
HOME=$(mktemp -d)
export HOME
ver=$(dpkg-query -W -f '${Version}' linuxcnc-uspace 2>/dev/null || echo unknown)
for f in *.rs274.nc; do
    n=${f%.rs274.nc}
    tbl=""
    [ -f "$n.tbl" ] && tbl="-t $n.tbl"
    { echo "# rs274 -g $tbl $f (LinuxCNC $ver), canonical calls as printed"
      # shellcheck disable=SC2086
      rs274 -g $tbl "$f" /dev/stdout </dev/null 2>&1 | grep -v '^executing'
    } > "$n.canon"
    if grep -v 'N\.\.\.\.\.' "$n.canon" | grep -qv '^#'; then
        echo "$n: rs274 reported an error:" >&2
        grep -v 'N\.\.\.\.\.' "$n.canon" >&2
        exit 1
    fi
    echo "$n.canon: $(grep -c 'STRAIGHT_\|ARC_FEED' "$n.canon") motions"
done

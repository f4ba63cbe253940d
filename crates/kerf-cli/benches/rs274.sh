#!/bin/sh
# Reference figure: LinuxCNC's stand-alone interpreter rs274 (the rs274ngc
# interpreter with a canon that prints) over the same input, output to
# /dev/null. Install: apt-get install -y --no-install-recommends linuxcnc-uspace
# Usage (workspace root): sh crates/kerf-cli/benches/rs274.sh [FILE.nc] [RUNS]
set -eu
f=${1:-bench-inputs/surface_1m.nc}
runs=${2:-3}
command -v rs274 >/dev/null || { echo "rs274 not installed (apt-get install linuxcnc-uspace)" >&2; exit 2; }
# rs274 keeps its tool table in $HOME/.tool.mmap and truncates it on every
# run: a HOME of this script's own keeps other rs274 runs out of it.
HOME=$(mktemp -d)
export HOME
tbl=$(mktemp)
echo "T1 P1 Z1.9685 D0.3937" > "$tbl"
lines=$(wc -l < "$f")
i=0
while [ $i -lt "$runs" ]; do
    /usr/bin/time -f '%e %U %M' -o "$tbl.t" rs274 -g -t "$tbl" "$f" /dev/null >/dev/null 2>&1 </dev/null
    echo "run $((i+1)): $(cat "$tbl.t")  (wall s, user s, peak RSS kB)"
    cat "$tbl.t" >> "$tbl.all"
    i=$((i+1))
done
med=$(sort -n "$tbl.all" | awk -v n="$runs" 'NR==int((n+1)/2){print $1}')
echo "median wall ${med}s for $lines blocks: $(awk -v l="$lines" -v s="$med" 'BEGIN{printf "%d", l/s}') blocks/s"
rm -f "$tbl" "$tbl.t" "$tbl.all"

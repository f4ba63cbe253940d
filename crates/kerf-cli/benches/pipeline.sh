#!/bin/sh
# The whole pipeline against LinuxCNC rs274 in the same run: for each input,
# rs274 (`rs274 -g -t TOOLS FILE /dev/null`), then `kerf run` with no
# output, --report, --toolpath and --plot, and `kerf expand`, RUNS times
# each, alternating.
# Prints the median wall time, the median CPU time (user + system), blocks/s
# and the ratio to rs274 for each, and the peak RSS.
#
#   cargo build --release -p kerf-cli
#   sh crates/kerf-cli/benches/pipeline.sh [RUNS] [FILE.nc ...]
#
# Defaults: 3 runs, bench-inputs/surface_1m.nc and drill_grid.nc. Needs GNU
# time (/usr/bin/time) and rs274 (apt-get install linuxcnc-uspace). The
# CPU-time ratio is the one to read on a loaded machine; kerf's CPU time
# includes the decimal-point check, which runs on a second thread.
set -eu
runs=${1:-3}
[ $# -gt 0 ] && shift
[ $# -gt 0 ] || set -- bench-inputs/surface_1m.nc bench-inputs/drill_grid.nc
KERF=${KERF:-target/release/kerf}
command -v rs274 >/dev/null || { echo "rs274 not installed (apt-get install linuxcnc-uspace)" >&2; exit 2; }
# rs274 keeps its tool table in $HOME/.tool.mmap and truncates it on every
# run: a HOME of this script's own keeps other rs274 runs out of it.
HOME=$(mktemp -d)
export HOME
[ -x "$KERF" ] || { echo "build first: cargo build --release -p kerf-cli" >&2; exit 2; }
tmp=$(mktemp -d)
echo "T1 P1 Z1.9685 D0.3937" > "$tmp/tools"
echo "T2 P2 Z1.9685 D0.3937" >> "$tmp/tools"
echo "T3 P3 Z1.9685 D0.3937" >> "$tmp/tools"
# one NAME CMD...: time CMD once, append "wall cpu rss" to $tmp/NAME.
one() {
    name=$1; shift
    /usr/bin/time -f '%e %U %S %M' -o "$tmp/t" "$@" >/dev/null 2>&1 </dev/null || true
    awk '{printf "%s %.3f %s\n", $1, $2 + $3, $4}' "$tmp/t" >> "$tmp/$name"
}
med() { # median of column $2 in file $1
    sort -n -k"$2" "$1" | awk -v n="$runs" -v c="$2" 'NR==int((n+1)/2){print $c}'
}
for f in "$@"; do
    base=$(basename "$f" .nc)
    blocks=$(wc -l < "$f")
    rm -f "$tmp"/r_* "$tmp"/k_*
    i=0
    while [ $i -lt "$runs" ]; do
        one r_rs274 rs274 -g -t "$tmp/tools" "$f" /dev/null
        one k_run "$KERF" run "$f" -q
        one k_report "$KERF" run "$f" -q --report "$tmp/out.json"
        one k_toolpath "$KERF" run "$f" -q --toolpath "$tmp/out.jsonl"
        one k_plot "$KERF" run "$f" -q --plot "$tmp/out.svg"
        one k_expand "$KERF" expand "$f" -q -o "$tmp/out.nc"
        i=$((i+1))
    done
    rw=$(med "$tmp/r_rs274" 1); rc=$(med "$tmp/r_rs274" 2)
    echo "$base ($blocks blocks), median of $runs:"
    printf '  %-18s %8s %8s %12s %9s %9s %9s\n' run "wall s" "cpu s" "blocks/s" "x rs274" "(cpu)" "peak kB"
    for k in r_rs274 k_run k_report k_toolpath k_plot k_expand; do
        w=$(med "$tmp/$k" 1); c=$(med "$tmp/$k" 2); m=$(med "$tmp/$k" 3)
        awk -v k="$k" -v w="$w" -v c="$c" -v m="$m" -v b="$blocks" -v rw="$rw" -v rc="$rc" \
            'BEGIN{printf "  %-18s %8.2f %8.2f %12d %9.1f %9.1f %9d\n", substr(k,3), w, c, b/(c>0?c:w), rw/w, rc/(c>0?c:1e-9), m}'
    done
    [ -f "$tmp/out.svg" ] && echo "  plot: $(wc -c < "$tmp/out.svg") bytes of SVG"
    [ -f "$tmp/out.jsonl" ] && echo "  toolpath: $(wc -l < "$tmp/out.jsonl") records"
    if [ -f "$tmp/out.nc" ]; then
        n=$(wc -l < "$tmp/out.nc"); w=$(med "$tmp/k_expand" 1)
        awk -v n="$n" -v w="$w" 'BEGIN{printf "  expand: %d output blocks, %.2f M output blocks/s (median wall)\n", n, n/w/1e6}'
    fi
done
rm -rf "$tmp"

#!/bin/sh
# Peak RSS and wall time of the release `kerf run` over the generated inputs.
# Run from the workspace root after
#   python3 ../shared/bench/gen_programs.py --out bench-inputs
#   cargo build --release -p kerf-cli
# Usage: sh crates/kerf-cli/benches/peak_rss.sh [FILE.nc ...]
set -u
kerf=${KERF:-target/release/kerf}
[ -x "$kerf" ] || { echo "build first: cargo build --release -p kerf-cli" >&2; exit 2; }
[ -x /usr/bin/time ] || { echo "needs GNU time (/usr/bin/time, Debian package 'time')" >&2; exit 2; }
[ $# -gt 0 ] || set -- bench-inputs/surface_1m.nc bench-inputs/surface_10m.nc
printf '%-34s %5s %9s %12s %12s\n' file exit wall_s peak_rss_kb blocks/s
for f in "$@"; do
    [ -f "$f" ] || { echo "missing $f (generate it, see docs/benchmarks.md)"; continue; }
    lines=$(wc -l < "$f")
    /usr/bin/time -f '%e %M' -o /tmp/kerf-rss.$$ "$kerf" run "$f" >/dev/null 2>/tmp/kerf-rss-err.$$
    rc=$?
    set -- $(tail -1 /tmp/kerf-rss.$$)
    printf '%-34s %5s %9s %12s %12.0f\n' "$f" "$rc" "$1" "$2" "$(awk -v l="$lines" -v s="$1" 'BEGIN{print (s>0)? l/s : 0}')"
    [ "$rc" = 0 ] || head -1 /tmp/kerf-rss-err.$$
done
rm -f /tmp/kerf-rss.$$ /tmp/kerf-rss-err.$$

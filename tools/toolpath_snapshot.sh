#!/usr/bin/env sh
# Writes the toolpath (and the exit status) of every example program, every
# corpus program and the benchmark inputs to OUT, so that two builds can be
# compared record for record:
#
#   sh tools/toolpath_snapshot.sh target/release/kerf /tmp/before
#   ... change, rebuild ...
#   sh tools/toolpath_snapshot.sh target/release/kerf /tmp/after
#   diff -r /tmp/before /tmp/after && echo identical
#
# The machine of an example is the one its NAME.expect.toml names; corpus
# programs run on the machine of their folder (lathe → puma-lathe).
# Benchmark inputs are taken from bench-inputs/ when present.
set -u
KERF=${1:?usage: toolpath_snapshot.sh KERF OUT}
OUT=${2:?usage: toolpath_snapshot.sh KERF OUT}
ROOT=$(cd "$(dirname "$0")/.." && pwd)
mkdir -p "$OUT"
one() { # name machine program [set...]
  name=$1; machine=$2; prog=$3; shift 3
  sets=""
  for s in "$@"; do sets="$sets --set $s"; done
  # shellcheck disable=SC2086
  "$KERF" run "$prog" --machine "$machine" --toolpath "$OUT/$name.jsonl" $sets \
    >/dev/null 2>"$OUT/$name.stderr"
  echo $? >"$OUT/$name.rc"
}
for f in "$ROOT"/examples/*/*.nc; do
  dir=$(basename "$(dirname "$f")"); base=$(basename "$f" .nc)
  exp="$ROOT/examples/$dir/$base.expect.toml"
  machine=$(sed -n 's/^machine *= *"\(.*\)"/\1/p' "$exp" 2>/dev/null | head -1)
  [ -n "$machine" ] || machine=hx-mc
  [ -f "$ROOT/examples/$dir/$machine" ] && machine="$ROOT/examples/$dir/$machine"
  one "ex_${dir}_$base" "$machine" "$f"
done
for f in "$ROOT"/../shared/corpus/*/*; do
  case "$f" in *.md) continue ;; esac
  dir=$(basename "$(dirname "$f")"); base=$(basename "$f")
  case "$dir" in lathe*) machine=puma-lathe ;; *) machine=hx-mc ;; esac
  one "corpus_${dir}_$base" "$machine" "$f"
done
for b in surface_1m drill_grid; do
  [ -f "$ROOT/bench-inputs/$b.nc" ] && one "bench_$b" hx-mc "$ROOT/bench-inputs/$b.nc"
done
exit 0

#!/bin/sh
# After run_kerf.sh: the reference beside kerf for every program here.
cd "$(dirname "$0")" || exit 2
for f in *.nc; do b=${f%.nc}; m=../../machines/hx-mc.toml
  case $b in puma*) m=../../machines/puma-lathe.toml;; hurco*) m=../../machines/hurco-lathe.toml;; lin_*) m=/tmp/mref/hx-linear.toml;; esac
  printf "%-18s " $b; python3 ../motion_reference.py $f /tmp/mref/$b.jsonl $m --report /tmp/mref/$b.json
done

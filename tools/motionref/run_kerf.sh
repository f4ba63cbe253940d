#!/bin/sh
# Run kerf on every program here: /tmp/mref/NAME.jsonl and NAME.json.
K=${KERF:-../../target/release/kerf}
mkdir -p /tmp/mref
for f in *.nc; do b=${f%.nc}; m=hx-mc
  case $b in puma*) m=puma-lathe;; hurco*) m=hurco-lathe;; esac
  $K run $f --machine $m --toolpath /tmp/mref/$b.jsonl --report /tmp/mref/$b.json >/tmp/mref/$b.out 2>&1 || echo "$b: kerf exit $?"
done

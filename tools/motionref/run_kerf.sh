#!/bin/sh
# Run kerf on every program here: /tmp/mref/NAME.jsonl and NAME.json.
cd "$(dirname "$0")" || exit 2
K=${KERF:-../../target/release/kerf}
mkdir -p /tmp/mref
sed "s/accel_type = \"bell\"/accel_type = \"linear\"/; s/^name = \"hx-mc\"/name = \"hx-linear\"/" ../../machines/hx-mc.toml > /tmp/mref/hx-linear.toml
for f in *.nc; do b=${f%.nc}; m=hx-mc; case $b in lin_*) m=/tmp/mref/hx-linear.toml;; esac
  case $b in puma*) m=puma-lathe;; hurco*) m=hurco-lathe;; esac
  $K run $f --machine $m --toolpath /tmp/mref/$b.jsonl --report /tmp/mref/$b.json >/tmp/mref/$b.out 2>&1 || echo "$b: kerf exit $?"
done

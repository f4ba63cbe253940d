#!/bin/sh
# Seeds fuzz/corpus/<target>/ from the example programs and the shared
# corpus (fuzz/corpus is gitignored; libFuzzer adds what it finds there).
set -eu
here=$(cd "$(dirname "$0")" && pwd)
root=$(dirname "$here")
for t in parse interp pipeline; do
    mkdir -p "$here/corpus/$t"
    for dir in "$root/examples" "$root/../shared/corpus" "$here/seeds"; do
        [ -d "$dir" ] || continue
        find "$dir" -type f \( -iname '*.nc' -o -iname '*.txt' \) | while read -r f; do
            name=$(printf "%s" "$f" | sed "s|^$root/||; s|^\.\./||; s|[/ ]|_|g")
            if [ "$t" = parse ]; then
                # byte 0 selects the line-source mode: one seed each way
                { printf '\000'; cat "$f"; } > "$here/corpus/$t/plain_$name"
                { printf '\001'; cat "$f"; } > "$here/corpus/$t/cont_$name"
            else
                cp "$f" "$here/corpus/$t/$name"
            fi
        done
    done
done
mkdir -p "$here/corpus/inputs"
cp "$here/seeds/inputs/"* "$here/corpus/inputs/"
echo "seeded: $(ls "$here/corpus/parse" | wc -l) parse, $(ls "$here/corpus/interp" | wc -l) interp, $(ls "$here/corpus/pipeline" | wc -l) pipeline, $(ls "$here/corpus/inputs" | wc -l) inputs"

#!/usr/bin/env bash
# Exports a sample guide with rigsmith-cli and checks the file with a real consumer.
#   check-export.sh validator|blender CLI GUIDE OUTDIR
set -euo pipefail
mode=$1 cli=$2 guide=$3 out=$4
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$out"
name=$(basename "$guide" .yml)
"$cli" build "$guide" -o "$out/$name.glb" --skeleton "$out/$name.skeleton.json"
"$cli" build "$guide" -o "$out/$name.gltf"
case "$mode" in
  validator)
    if [ ! -d "$here/node_modules/gltf-validator" ]; then
      echo "gltf-validator is not installed: run ./test.sh (it runs npm ci in tests/tools)" >&2
      exit 1
    fi
    node "$here/validate-gltf.js" "$out/$name.glb"
    node "$here/validate-gltf.js" "$out/$name.gltf" ;;
  blender)
    command -v blender >/dev/null || { echo "blender is not installed: run ./test.sh" >&2; exit 1; }
    for f in "$out/$name.glb" "$out/$name.gltf"; do
      status=0
      blender -b --factory-startup --python-exit-code 1 --python "$here/blender-check.py" -- \
        "$f" "$out/$name.skeleton.json" >"$f.blender.log" 2>&1 || status=$?
      grep -E "^(CHECK|ERROR|Traceback|  File|[A-Za-z]*Error)" "$f.blender.log" || true
      if [ "$status" -ne 0 ] || ! grep -q "^CHECK" "$f.blender.log"; then
        echo "Blender check failed for $f (log: $f.blender.log)" >&2
        exit 1
      fi
    done ;;
  *) echo "unknown mode $mode" >&2; exit 2 ;;
esac

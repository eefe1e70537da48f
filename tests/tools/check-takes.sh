#!/usr/bin/env bash
# The range of motion as one clip per controller (--rom-clips per-control,
# issue 21 item 3) as .glb and .fbx, read by one consumer: every clip of the
# export's reference JSON comes in under its name and lasts as long as it says.
#   three:   GLTFLoader and FBXLoader (compare-three.mjs --reference; the clips
#            also agree at 4x the key rate within 1e-4 m)
#   blender: Blender's FBX and glTF importers, one action per take / animation (blender-takes.py)
# usage: check-takes.sh three|blender CLI GUIDE OUTDIR
set -euo pipefail
mode=$1 cli=$2 guide=$3 out=$4
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$out"
name=$(basename "$guide" .yml)
"$cli" build "$guide" --rom --rom-clips per-control --reference "$out/$name.json" -o "$out/$name.glb"
"$cli" build "$guide" --rom --rom-clips per-control -o "$out/$name.fbx"
case "$mode" in
  three)
    if [ ! -d "$here/node_modules/three" ]; then
      echo "three is not installed: run ./test.sh (it runs npm ci in tests/tools)" >&2
      exit 1
    fi
    node "$here/compare-three.mjs" "$out/$name.glb" "$out/$name.fbx" 1e-4 --reference "$out/$name.json" ;;
  blender)
    command -v blender >/dev/null || { echo "blender is not installed: run ./test.sh" >&2; exit 1; }
    status=0
    blender -b --factory-startup --python-exit-code 1 --python "$here/blender-takes.py" -- \
      "$out/$name.fbx" "$out/$name.glb" "$out/$name.json" >"$out/$name.blender.log" 2>&1 || status=$?
    grep -E "^(CHECK|ERROR|Traceback|  File|[A-Za-z]*Error)" "$out/$name.blender.log" || true
    if [ "$status" -ne 0 ] || ! grep -q "^CHECK" "$out/$name.blender.log"; then
      echo "Blender takes check failed (log: $out/$name.blender.log)" >&2
      exit 1
    fi ;;
  *) echo "unknown mode $mode" >&2; exit 2 ;;
esac

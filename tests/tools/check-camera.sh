#!/usr/bin/env bash
# Exports a guide with a util.camera (the vehicle sample) with its range of
# motion and a keyed camera clip, as .glb and binary .fbx in one preset, and
# checks the cameras with headless Blender (blender-camera.py): one camera
# object per util.camera, at the rig camera's world position and look
# direction at sampled key times of every clip, its lens (glTF yfov; FBX
# focal length curve). The glb also goes through the Khronos validator.
# usage: check-camera.sh CLI GUIDE CLIP.yml OUTDIR PRESET [BUILD OPTION...]
set -euo pipefail
cli=$1 guide=$2 clip=$3 out=$4 preset=$5
extra=("${@:6}")
here=$(cd "$(dirname "$0")" && pwd)
command -v blender >/dev/null || { echo "blender is not installed: run ./test.sh" >&2; exit 1; }
mkdir -p "$out"
name=$(basename "$guide" .yml)-camera-$preset
options=(--preset "$preset" --rom --clip "$clip" --proxy-mesh 2000 "${extra[@]}")
"$cli" build "$guide" "${options[@]}" --reference "$out/$name.json" -o "$out/$name.glb"
"$cli" build "$guide" "${options[@]}" -o "$out/$name.fbx"
if [ -d "$here/node_modules/gltf-validator" ]; then
  node "$here/validate-gltf.js" "$out/$name.glb"
fi
status=0
for f in "$out/$name.glb" "$out/$name.fbx"; do
  blender -b --factory-startup --python-exit-code 1 --python "$here/blender-camera.py" -- \
    "$f" "$out/$name.json" >"$f.blender.log" 2>&1 || status=1
  grep -E "^(CHECK|ERROR|Traceback|  File|[A-Za-z]*Error)" "$f.blender.log" || true
  grep -q "^CHECK" "$f.blender.log" || status=1
done
exit $status

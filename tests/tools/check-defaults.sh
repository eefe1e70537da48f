#!/usr/bin/env bash
# Cleanup's recorded default values as consumers see them: builds GUIDE with
# --cleanup --controllers as .glb and .fbx, runs the Khronos validator on the
# .glb (0 errors, 0 warnings) and reads both files back in headless Blender
# (blender-defaults.py): every controller's defaults, taken from the glb's own
# JSON (node extras rig.defaults), must come back as custom properties of the
# controller's empty, from the glTF extras and from the FBX user properties.
# usage: check-defaults.sh CLI GUIDE OUTDIR
set -euo pipefail
cli=$1 guide=$2 out=$3
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$out"
name=$(basename "$guide" .yml)-defaults
"$cli" build "$guide" --cleanup --controllers --proxy-mesh 2000 -o "$out/$name.glb"
"$cli" build "$guide" --cleanup --controllers --proxy-mesh 2000 -o "$out/$name.fbx"
if [ -d "$here/node_modules/gltf-validator" ]; then
  node "$here/validate-gltf.js" "$out/$name.glb"
else
  echo "gltf-validator is not installed: run ./test.sh (it runs npm ci in tests/tools)" >&2
  exit 1
fi
command -v blender >/dev/null || { echo "blender is not installed: run ./test.sh" >&2; exit 1; }
status=0
blender -b --factory-startup --python-exit-code 1 --python "$here/blender-defaults.py" -- \
  "$out/$name.glb" "$out/$name.fbx" >"$out/$name.blender.log" 2>&1 || status=$?
grep -E "^(CHECK|ERROR|Traceback|  File|[A-Za-z]*Error)" "$out/$name.blender.log" || true
exit $status

#!/usr/bin/env bash
# Exports a sample guide with rigsmith-cli in one preset, in every format (.glb,
# .gltf + .bin, binary .fbx) with a generated skinned mesh bound, plus a .glb with
# every option (controllers, range-of-motion clip, current pose), and checks the
# files with a real consumer:
#   validator: the Khronos glTF validator, 0 errors and 0 warnings (glTF files);
#   blender, blender-fbx: headless Blender (glTF files, FBX files), one armature, one root, names, parents, heads and
#              weights within 1e-4 of the export reference (every file); the FBX
#              also without a mesh (still one armature) and with every option (the
#              rest pose from the BindPose, the clip's action with scale curves
#              moving only where the reference's scale changes); FBX unit scale 1
#              for the metres presets.
# usage: check-export.sh validator|blender|blender-fbx CLI GUIDE OUTDIR PRESET [BUILD OPTION...]
# (BUILD OPTIONs go to every build: --force for a preset that refuses the rig)
set -euo pipefail
mode=$1 cli=$2 guide=$3 out=$4 preset=$5
extra=("${@:6}")
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$out"
name=$(basename "$guide" .yml)-$preset
mesh=(--proxy-mesh 8000 "${extra[@]}") # 6 rings a bone: weights like 0.7/0.3, not exact in binary
"$cli" build "$guide" --preset "$preset" "${mesh[@]}" --reference "$out/$name.json" -o "$out/$name.glb"
"$cli" build "$guide" --preset "$preset" "${mesh[@]}" -o "$out/$name.gltf"
"$cli" build "$guide" --preset "$preset" "${mesh[@]}" --controllers --rom --current-pose --reference "$out/$name-all.json" -o "$out/$name-all.glb"
case "$mode" in
  validator)
    if [ ! -d "$here/node_modules/gltf-validator" ]; then
      echo "gltf-validator is not installed: run ./test.sh (it runs npm ci in tests/tools)" >&2
      exit 1
    fi
    for f in "$out/$name.glb" "$out/$name.gltf" "$out/$name-all.glb"; do
      node "$here/validate-gltf.js" "$f"
    done ;;
  blender|blender-fbx)
    command -v blender >/dev/null || { echo "blender is not installed: run ./test.sh" >&2; exit 1; }
    check() { # FILE REFERENCE [blender-check.py options]
      local f=$1 status=0
      blender -b --factory-startup --python-exit-code 1 --python "$here/blender-check.py" -- \
        "$@" >"$f.blender.log" 2>&1 || status=$?
      grep -E "^(CHECK|ERROR|Traceback|  File|[A-Za-z]*Error)" "$f.blender.log" || true
      if [ "$status" -ne 0 ] || ! grep -q "^CHECK" "$f.blender.log"; then
        echo "Blender check failed for $f (log: $f.blender.log)" >&2
        exit 1
      fi
    }
    if [ "$mode" = blender ]; then
      check "$out/$name.glb" "$out/$name.json"
      check "$out/$name.gltf" "$out/$name.json"
      check "$out/$name-all.glb" "$out/$name-all.json" --animated
      exit 0
    fi
    "$cli" build "$guide" --preset "$preset" "${mesh[@]}" -o "$out/$name.fbx"
    # No mesh: still one armature (LimbNodes). Every option: the bind pose and the clip.
    "$cli" build "$guide" --preset "$preset" "${extra[@]}" --reference "$out/$name-bare.json" -o "$out/$name-bare.fbx"
    "$cli" build "$guide" --preset "$preset" "${mesh[@]}" --controllers --rom --current-pose -o "$out/$name-all.fbx"
    fbx_scale=1 # metres presets import at scale 1; Unreal's centimetres at 0.01
    [ "$preset" = unreal ] && fbx_scale=0.01
    check "$out/$name.fbx" "$out/$name.json" --unit-scale "$fbx_scale"
    check "$out/$name-bare.fbx" "$out/$name-bare.json" --unit-scale "$fbx_scale"
    check "$out/$name-all.fbx" "$out/$name-all.json" --unit-scale "$fbx_scale" --animated ;;
  *) echo "unknown mode $mode" >&2; exit 2 ;;
esac

#!/usr/bin/env bash
# The bound human exported by rigsmith-cli (.glb, .fbx, and .fbx in the Unreal
# preset) imported by headless Blender: blender-check.py compares the armature
# and every vertex's weights with the export reference (within 1e-4, vertices
# matched by place), check-blender-skin.py the UVs, materials and texture of
# .glb and .fbx, the FBX's texture embedded and, with --textures relative,
# copied beside it (into a folder of its own, read back from there).
# usage: check-blender-skin.sh CLI [OUTDIR]   (CLI: build/app/rigsmith-cli)
set -euo pipefail
cli=$1
here=$(cd "$(dirname "$0")" && pwd)
out=${2:-$(mktemp -d)}
mkdir -p "$out"
cp "$here/../data/Skin/human/guide.yml" "$out/guide.yml"
"$cli" skin bind "$out/guide.yml" > /dev/null 2>&1
"$cli" build "$out/guide.yml" --reference "$out/human.json" -o "$out/human.glb"
"$cli" build "$out/guide.yml" -o "$out/human.fbx"
mkdir -p "$out/relative"
"$cli" build "$out/guide.yml" --textures relative -o "$out/relative/human.fbx"
"$cli" build "$out/guide.yml" --preset unreal --reference "$out/human-unreal.json" -o "$out/human-unreal.fbx"
run() {
  blender -b --factory-startup --python-exit-code 1 --python "$@" > "$out/blender.log" 2>&1 || { grep -E "^(ERROR|Traceback)|Error" "$out/blender.log"; exit 1; }
  grep -E "^(CHECK|ERROR)" "$out/blender.log"
}
run "$here/blender-check.py" -- "$out/human.glb" "$out/human.json"
run "$here/blender-check.py" -- "$out/human.fbx" "$out/human.json"
run "$here/blender-check.py" -- "$out/human-unreal.fbx" "$out/human-unreal.json"
run "$here/check-blender-skin.py" -- "$out/human.glb" "$out/human.fbx" --textures embedded
run "$here/check-blender-skin.py" -- "$out/human.glb" "$out/relative/human.fbx" --textures relative
echo ok

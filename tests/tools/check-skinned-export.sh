#!/usr/bin/env bash
# rigsmith-cli build -o with a character (issue 19): on a copy of the guide
# fitted to the human of assimp-testmodels, build without weights is refused
# naming the mesh (--no-meshes and --force export), then skin bind + build
# -o .glb in every preset (and .gltf, .fbx) gives files the Khronos validator
# accepts (0 errors, 0 warnings) holding both meshes with NORMAL, TEXCOORD_0,
# at most 4 influences normalised, and the eyes' material with its PNG inside.
# usage: check-skinned-export.sh CLI GUIDE   (exit 77: skipped, no human.zae)
set -euo pipefail
cli=$1 guide=$2
here=$(cd "$(dirname "$0")" && pwd)
[ -f /usr/share/assimp/models/Collada/human.zae ] || { echo "assimp-testmodels is not installed"; exit 77; }
[ -d "$here/node_modules/gltf-validator" ] || { echo "gltf-validator is not installed: run ./test.sh (npm ci in tests/tools)" >&2; exit 1; }
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
cp "$guide" "$dir/guide.yml"

if "$cli" build "$dir/guide.yml" -o "$dir/unbound.glb" 2> "$dir/err.txt"; then echo "exported meshes without weights"; exit 1; fi
grep -q "mesh 'human-baseMesh' of human.zae: it has no skin weights" "$dir/err.txt" || { cat "$dir/err.txt"; exit 1; }
[ ! -e "$dir/unbound.glb" ] || { echo "a refused export wrote a file"; exit 1; }
"$cli" build "$dir/guide.yml" --no-meshes -o "$dir/joints.glb" 2> /dev/null
"$cli" build "$dir/guide.yml" --force -o "$dir/forced.glb" 2> "$dir/forced.txt"
grep -q "exported anyway (forced)" "$dir/forced.txt" || { cat "$dir/forced.txt"; exit 1; }

"$cli" skin bind "$dir/guide.yml" > /dev/null
for preset in gltf unreal unity; do
  "$cli" build "$dir/guide.yml" --preset "$preset" -o "$dir/human-$preset.glb" 2> "$dir/build.txt" || { cat "$dir/build.txt"; exit 1; }
  node "$here/validate-gltf.js" "$dir/human-$preset.glb"
done
"$cli" build "$dir/guide.yml" -o "$dir/human.gltf" 2> /dev/null
node "$here/validate-gltf.js" "$dir/human.gltf"
"$cli" build "$dir/guide.yml" --preset unreal -o "$dir/human.fbx" 2> /dev/null
test -s "$dir/human.fbx"
python3 - "$dir/human-gltf.glb" <<'PY'
import json, struct, sys
data = open(sys.argv[1], 'rb').read()
n = struct.unpack('<I', data[12:16])[0]
gltf = json.loads(data[20:20 + n])
bin_start = 20 + n + 8
assert [m['name'] for m in gltf['meshes']] == ['human-baseMesh', 'human-highpolyeyesMesh'], gltf['meshes']
def floats(index, width):
    a = gltf['accessors'][index]
    v = gltf['bufferViews'][a['bufferView']]
    start = bin_start + v.get('byteOffset', 0) + a.get('byteOffset', 0)
    assert a['componentType'] == 5126
    return [struct.unpack_from('<%df' % width, data, start + 4 * width * i) for i in range(a['count'])]
for mesh in gltf['meshes']:
    attributes = mesh['primitives'][0]['attributes']
    assert {'POSITION', 'NORMAL', 'TEXCOORD_0', 'JOINTS_0', 'WEIGHTS_0'} <= set(attributes), attributes
    weights = floats(attributes['WEIGHTS_0'], 4)
    assert all(abs(sum(w) - 1) < 1e-4 and min(w) >= 0 for w in weights), mesh['name']
    assert sum(1 for w in weights if sum(1 for x in w if x > 0) >= 3) > 0 or mesh['name'] != 'human-baseMesh'
eyes = gltf['materials'][gltf['meshes'][1]['primitives'][0]['material']]
texture = gltf['textures'][eyes['pbrMetallicRoughness']['baseColorTexture']['index']]
image = gltf['images'][texture['source']]
assert image['mimeType'] == 'image/png' and image['name'] == 'brown_eye.png', image
view = gltf['bufferViews'][image['bufferView']]
assert data[bin_start + view.get('byteOffset', 0):][:8] == b'\x89PNG\r\n\x1a\n'
print('meshes, weights and the embedded texture: ok')
PY
echo "ok"

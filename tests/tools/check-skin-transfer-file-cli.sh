#!/usr/bin/env bash
# rigsmith-cli skin transfer from a skinned model file (issue 20 item 6): the
# human of assimp-testmodels bound by `skin bind` and exported by `build -o
# .glb` is the SOURCE, the original human.zae the TARGET. Same topology: 1:1
# (the eyes: one influence); through the uber chunk (--uber, closest point on
# all the glb's triangles) the dominant joint of >= 98% of the vertices is the
# one the guide's own weights give; -o .glb writes the target skinned on the
# source's skeleton (the Khronos validator accepts it when tests/tools has
# node_modules). A model file without a skinned mesh is refused (exit 1,
# nothing written), -o .fbx is a usage error (exit 2).
# usage: check-skin-transfer-file-cli.sh CLI GUIDE   (exit 77: skipped, no human.zae)
set -euo pipefail
cli=$1 guide=$2
here=$(cd "$(dirname "$0")" && pwd)
human=/usr/share/assimp/models/Collada/human.zae
[ -f "$human" ] || { echo "assimp-testmodels is not installed"; exit 77; }
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail() { echo "FAILED: $*"; for f in "$dir"/*.txt; do echo "--- $f"; head -20 "$f"; done; exit 1; }
cd "$dir"
cp "$guide" g.yml
"$cli" skin bind g.yml > /dev/null 2>&1 || fail "bind"
"$cli" build g.yml -o human.glb > /dev/null 2>&1 || fail "build -o human.glb"
"$cli" skin export g.yml -o bound.rschunks > /dev/null || fail "export"

"$cli" skin transfer human.glb "$human" -o same.rschunks --json same.json > same.txt || fail "transfer onto the same model"
grep -q "^source: 2 skinned meshes, 87 joints" same.txt || fail "source line"
python3 -c '
import json, sys
m = {x["mesh"]: x for x in json.load(open(sys.argv[1]))["meshes"]}
base, eyes = m["human-baseMesh"], m["human-highpolyeyesMesh"]
assert base["route"] == "one-to-one" and base["oneToOne"] == 53512, base
assert eyes["route"] == "single-influence" and eyes["singleInfluence"] == 4080, eyes
' same.json || fail "same model: 1:1 and single influence"
"$cli" skin transfer human.glb "$human" -o uber.rschunks --uber --json uber.json > uber.txt || fail "transfer through the uber chunk"
python3 -c '
import json, sys
m = {x["mesh"]: x for x in json.load(open(sys.argv[1]))["meshes"]}
base = m["human-baseMesh"]
assert base["route"] == "fallback" and base["source"] == "uber chunk" and base["closestPoint"] == 53512, base
' uber.json || fail "uber: every vertex by closest point"

# Dominant joints per vertex: the transfers against the guide's own weights.
for f in bound same uber; do "$cli" skin info $f.rschunks --mesh human-baseMesh --limit 100000 > $f-info.txt; done
python3 - bound-info.txt same-info.txt uber-info.txt <<'PY' || fail "dominant joints"
import re, sys
def dominant(path):
    out = {}
    for line in open(path):
        m = re.match(r"^\s+(\d+) id \d+ .* weights (.*?)(?: neighbours.*)?$", line)
        if m:
            w = m.group(2).split()
            pairs = [(float(w[k + 1]), w[k]) for k in range(0, len(w), 2)]
            out[int(m.group(1))] = max(pairs)[1]
    return out
bound = dominant(sys.argv[1])
assert len(bound) == 53512, len(bound)
for path, least in ((sys.argv[2], 0.999), (sys.argv[3], 0.98)):
    other = dominant(path)
    agree = sum(1 for v, j in bound.items() if other.get(v) == j) / len(bound)
    print("%s: dominant joint agrees at %.2f%% of the vertices" % (path, 100 * agree))
    assert agree >= least, (path, agree)
PY

"$cli" skin transfer human.glb "$human" -o out.glb --uber > glb.txt || fail "-o .glb"
grep -q "^skinned meshes: out.glb" glb.txt || fail "-o .glb line"
python3 - out.glb <<'PY' || fail "out.glb holds both meshes with 4 normalised weights on 87 joints"
import json, struct, sys
data = open(sys.argv[1], 'rb').read()
n = struct.unpack('<I', data[12:16])[0]
gltf = json.loads(data[20:20 + n])
bin_start = 20 + n + 8
assert [m['name'] for m in gltf['meshes']] == ['human-baseMesh', 'human-highpolyeyesMesh'], gltf['meshes']
assert len(gltf['skins']) == 1 and len(gltf['skins'][0]['joints']) == 87, len(gltf['skins'][0]['joints'])
for mesh in gltf['meshes']:
    a = gltf['accessors'][mesh['primitives'][0]['attributes']['WEIGHTS_0']]
    v = gltf['bufferViews'][a['bufferView']]
    start = bin_start + v.get('byteOffset', 0) + a.get('byteOffset', 0)
    for i in range(a['count']):
        w = struct.unpack_from('<4f', data, start + 16 * i)
        assert abs(sum(w) - 1) < 1e-4 and min(w) >= 0, (mesh['name'], i, w)
PY
if [ -d "$here/node_modules/gltf-validator" ]; then
  node "$here/validate-gltf.js" out.glb > validator.txt || fail "the Khronos validator refuses out.glb"
else
  echo "gltf-validator is not installed (npm ci in tests/tools): out.glb not validated"
fi
"$cli" skin transfer out.glb "$human" -o back.rschunks > back.txt || fail "the written .glb as a source"
grep -q "human-baseMesh: 53512 vertices, one-to-one" back.txt || fail "the written .glb carries the target's vertices"

# Refusals: nothing written.
if "$cli" skin transfer /usr/share/assimp/models/OBJ/box.obj "$human" -o x.rschunks 2> box.txt; then fail "an unskinned source transferred"; fi
grep -q "box.obj: error: no mesh in the file is skinned" box.txt || fail "unskinned source message"
set +e
"$cli" skin transfer human.glb "$human" -o x.fbx 2> fbx.txt; code=$?
set -e
[ "$code" = 2 ] || fail "-o x.fbx exited $code, not 2"
[ ! -e x.rschunks ] && [ ! -e x.fbx ] || fail "a failed transfer wrote a file"
echo "skin transfer from a skinned model file: ok"

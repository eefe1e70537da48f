#!/usr/bin/env bash
# A changed model is re-fitted by the CLI's build (issue 20 item 5): skin bind
# keeps the meshes as bound beside the weights (GUIDE.weights.rschunks); the
# model file is then replaced by a denser remesh of the same body; `build -o`
# re-fits the weights from the meshes as bound (reported: matched 1:1,
# transferred, inpainted) and exports the skinned mesh instead of refusing it.
# Without the kept meshes the export refuses the changed mesh, as before.
set -euo pipefail
cli=$1
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail() { echo "FAILED: $*"; for f in "$dir"/*.txt; do echo "--- $f"; cat "$f"; done; exit 1; }
cd "$dir"
python3 - <<'PY'
import math
def cylinder(path, rings, sides):
    with open(path, "w") as out:
        out.write("o body\n")
        for i in range(rings):
            for k in range(sides):
                a = 2 * math.pi * k / sides
                out.write("v %f %f %f\n" % (0.15 * math.cos(a), 0.8 + 0.7 * i / (rings - 1), 0.15 * math.sin(a)))
        for i in range(rings - 1):
            for k in range(sides):
                a = i * sides + k + 1; b = i * sides + (k + 1) % sides + 1
                out.write(f"f {a} {a + sides} {b}\nf {b} {a + sides} {b + sides}\n")
cylinder("body.obj", 15, 12)
cylinder("remesh.obj", 22, 16)
PY
"$cli" new g.yml --name hero > /dev/null
"$cli" add g.yml world.character > /dev/null
"$cli" add g.yml spine.torso --under world --at 0,0.9,0 > /dev/null
"$cli" model add g.yml body.obj > /dev/null
"$cli" skin bind g.yml --method envelope > /dev/null 2>&1 || fail "bind"
[ -f g.weights.rschunks ] || fail "skin bind keeps the meshes as bound in g.weights.rschunks"
"$cli" skin info g.weights.rschunks --limit 0 > kept.txt || fail "the kept meshes read back"
grep -q "body" kept.txt || fail "the kept meshes name body"

cp remesh.obj body.obj
"$cli" build g.yml -o out.glb > build.txt 2>&1 || fail "build after a remesh exports"
grep -Eq "mesh 'body' changed since it was bound \([0-9]+ vertices then, [0-9]+ now\): its weights were re-fitted" build.txt ||
  fail "the build reports the re-fit"
grep -q "inpainted" build.txt || fail "the report counts inpainted vertices"
[ -s out.glb ] || fail "the export is written"

rm g.weights.rschunks
if "$cli" build g.yml -o refused.glb > refused.txt 2>&1; then fail "a changed mesh without the kept meshes is refused"; fi
grep -q "changed since it was bound" refused.txt || fail "the refusal says why"
[ ! -e refused.glb ] || fail "nothing is written when refused"
echo "build re-fits a remeshed model from the meshes as bound"

#!/usr/bin/env bash
# rigsmith-cli skin export / import / transfer (issue 20 items 1, 4, 5, 6) on a
# generated character (a world and a spine, a cylinder body and a belt, bound
# by envelope): export selections (vertices, joints), missing influences
# (stop lists them, create adds them to the guide, a name map maps them), import onto a
# selection and --append keep the other vertices' weights, a weight depot
# round trip where the newest chunk wins, skin transfer onto another mesh
# file, progress on stderr. Failures exit 1 and write nothing; usage errors 2.
set -euo pipefail
cli=$1
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail() { echo "FAILED: $*"; for f in "$dir"/*.txt; do echo "--- $f"; cat "$f"; done; exit 1; }
cd "$dir"
python3 - <<'EOF'
import math
def cylinder(name, radius, y0, y1, rings, sides, out, first):
    out.write(f"o {name}\n")
    for i in range(rings):
        for k in range(sides):
            a = 2 * math.pi * k / sides
            out.write("v %f %f %f\n" % (radius * math.cos(a), y0 + (y1 - y0) * i / (rings - 1), radius * math.sin(a)))
    for i in range(rings - 1):
        for k in range(sides):
            a = first + i * sides + k + 1; b = first + i * sides + (k + 1) % sides + 1
            out.write(f"f {a} {a + sides} {b}\nf {b} {a + sides} {b + sides}\n")
    return rings * sides
with open("body.obj", "w") as f:
    n = cylinder("body", 0.15, 0.8, 1.5, 15, 12, f, 0)
    cylinder("belt", 0.17, 0.95, 1.05, 3, 12, f, n)
with open("remesh.obj", "w") as f:
    cylinder("body", 0.15, 0.8, 1.5, 22, 16, f, 0)
EOF
"$cli" new g.yml --name hero > /dev/null
"$cli" add g.yml world.character > /dev/null
"$cli" add g.yml spine.torso --under world --at 0,0.9,0 > /dev/null
"$cli" model add g.yml body.obj > /dev/null
"$cli" skin bind g.yml --method envelope > /dev/null 2>&1
"$cli" skin export g.yml -o all.rschunks > /dev/null || fail "export"
cp g.weights envelope.weights

# Export selections: vertex ranges, the vertices joints influence, bad names.
"$cli" skin export g.yml -o range.rschunks --vertices body:0-99,120 > /dev/null || fail "--vertices export"
"$cli" skin info range.rschunks --limit 0 > range.txt
grep -q "exported vertices: 101 (a subset)" range.txt && ! grep -q "chunk 1" range.txt || fail "--vertices exports 101 vertices of body only"
"$cli" skin export g.yml -o top.rschunks --joints sk_spine4 > /dev/null || fail "--joints export"
"$cli" skin info top.rschunks --limit 100000 > top.txt
python3 -c '
import re, sys
text = open(sys.argv[1]).read()
rows = re.findall(r"^    \d+ id \d+ .*$", text, re.M)
m = re.search(r"exported vertices: (\d+) \(a subset\)", text)
assert m and int(m.group(1)) == len(rows) > 0, (m, len(rows))
assert all(re.search(r"sk_spine4 (?!0 )", r) for r in rows), "a vertex without sk_spine4"
' top.txt || fail "--joints exports only vertices sk_spine4 weights, with all their weights"
if "$cli" skin export g.yml -o x.rschunks --joints sk_nose 2> nose.txt; then fail "an unknown joint exported"; fi
grep -q "'sk_nose' is not a skin joint" nose.txt || fail "unknown joint message"
if "$cli" skin export g.yml -o x.rschunks --vertices body:0-5000 2> far.txt; then fail "a vertex out of range exported"; fi
grep -q "mesh 'body' has 1008 vertices: vertex 5000 is not one of them" far.txt || fail "vertex range message"

# Missing influences: the same character with its spine renamed (another
# instance id and name), so no chunk influence is a joint of its rig.
sed -e 's/^  - id: 2$/  - id: 5/' -e 's/^    name: spine$/    name: torso/' g.yml > torso.yml
if "$cli" skin import torso.yml all.rschunks 2> stop.txt; then fail "missing influences were imported"; fi
grep -q "influence 'sk_spine_hips' (weighting meshes 'body', 'belt') is not a skin joint of the rig" stop.txt || fail "stop message"
[ "$(grep -c "is not a skin joint of the rig" stop.txt)" = 5 ] || fail "stop lists every missing influence"
[ ! -e torso.weights ] || fail "a stopped import wrote weights"
cp torso.yml torso-before.yml
"$cli" skin import torso.yml all.rschunks --missing create --json create.json > create-out.txt 2> create.txt || fail "create"
python3 -c '
import json, sys
r = json.load(open(sys.argv[1]))["influences"]
assert r["created"] == 5 and r["mapped"] == 0 and r["identity"] == 1, r
assert all(m["how"] == "created" and m["to"] == m["influence"] for m in r["moved"]), r
' create.json || fail "create makes a joint named as each spine influence"
grep -q "created joint: sk_spine4 (influence sk_spine4) under sk_spine3" create-out.txt || fail "create names each joint and its parent"
[ "$(grep -c "template: core.joints" torso.yml)" = 5 ] || fail "create saves five core.joints instances into the guide"
[ -z "$(ls -A | grep '\.tmp$' || true)" ] || fail "create left temp files"
python3 - <<'PY' || fail "the created joints sit where the influences were bound"
import re
text = open("torso.yml").read()
hips = re.search(r"names:\n\s+skin\.0: sk_spine_hips\n\s+joints:\n\s+- \{id: \d+, t: \[([^]]*)\]", text)
assert hips, text
t = [float(x) for x in hips.group(1).split(",")]
assert abs(t[0]) < 1e-6 and abs(t[2]) < 1e-6 and 0.8 < t[1] < 1.0, t # under the world root joint (at the origin): at the hips' height
PY
"$cli" skin import torso.yml all.rschunks --json again.json > /dev/null 2>&1 || fail "the created joints are found by name on the next import"
grep -q '"created": 0' again.json && grep -q '"name": 5' again.json || fail "the next import matches the created joints by name"
cp torso-before.yml torso.yml
rm -f torso.weights torso.weights.rschunks
printf '# old spine -> torso\nsk_spine_hips: sk_torso_hips\nsk_spine1: sk_torso1\n"sk_spine2" = sk_torso2\n' > names.yml
"$cli" skin import torso.yml all.rschunks --name-map names.yml --missing create --json mapped.json > /dev/null 2>&1 || fail "map + create"
python3 -c '
import json, sys
r = json.load(open(sys.argv[1]))["influences"]
assert r["mapped"] == 3 and r["created"] == 2, r
to = {m["influence"]: (m["how"], m["to"]) for m in r["moved"]}
assert to["sk_spine1"] == ("mapped", "sk_torso1") and to["sk_spine4"] == ("created", "sk_spine4"), to
' mapped.json || fail "a name map maps, and create makes joints for the rest"
grep -q "sk_spine3" torso.yml && ! grep -q "sk_spine1" torso.yml || fail "create makes only the joints the map leaves missing"
cp torso-before.yml torso.yml
rm -f torso.weights
if "$cli" skin import torso.yml all.rschunks --missing map --map sk_spine_hips=sk_torso_hips 2> map.txt; then fail "a partial map imported"; fi
grep -q "influence 'sk_spine1' (weighting meshes 'body', 'belt') is not a skin joint of the rig and the name map does not name it" map.txt || fail "map message"
[ ! -e torso.weights ] || fail "a failed map wrote weights"
set +e
"$cli" skin import torso.yml all.rschunks --missing map 2> usage.txt; code=$?
set -e
[ "$code" = 2 ] && grep -q -- "--missing map needs a name map" usage.txt || fail "--missing map without a map is a usage error"
printf 'sk_spine1 sk_torso1\n' > bad.yml
if "$cli" skin import torso.yml all.rschunks --name-map bad.yml 2> bad.txt; then fail "a bad name map was read"; fi
grep -q "bad.yml:1:1: error: expected 'OLD=NEW' or 'OLD: NEW'" bad.txt || fail "name map message"

# Onto a selection, and --append: other vertices keep their weights.
"$cli" skin bind g.yml --method closest > /dev/null 2>&1
cp g.weights closest.weights
"$cli" skin import g.yml all.rschunks --vertices body:0-99 --json selection.json > /dev/null || fail "selection import"
python3 -c '
import json, sys
m = json.load(open(sys.argv[1]))["meshes"]
assert len(m) == 1 and m[0]["mesh"] == "body" and m[0]["written"] == 100 and m[0]["kept"] == 908, m
' selection.json || fail "a selection writes 100 vertices and keeps 908"
"$cli" skin export g.yml -o after.rschunks --mesh body > /dev/null
"$cli" skin info after.rschunks --from 50 --limit 1 | grep "^    50 id" | sed 's/ neighbours.*//' > after50.txt
"$cli" skin info all.rschunks --mesh body --from 50 --limit 1 | grep "^    50 id" | sed 's/ neighbours.*//' > env50.txt
cmp -s after50.txt env50.txt || fail "a selected vertex got the chunk's weights"
"$cli" skin export g.yml -o closest.rschunks --mesh body > /dev/null
"$cli" skin info after.rschunks --from 500 --limit 1 | grep "^    500 id" > after500.txt
"$cli" skin info closest.rschunks --from 500 --limit 1 | grep "^    500 id" > closest500.txt
cmp -s after500.txt closest500.txt || fail "a vertex outside the selection kept its weights"
cp closest.weights g.weights
"$cli" skin import g.yml range.rschunks --append --json append.json > /dev/null || fail "append import"
python3 -c '
import json, sys
r = json.load(open(sys.argv[1]))
body = [m for m in r["meshes"] if m["mesh"] == "body"][0]
assert r["append"] and body["route"] == "one-to-one" and body["written"] == 101 and body["kept"] == 907, body
' append.json || fail "--append writes the chunk's 101 vertices and keeps the rest"
"$cli" skin import g.yml range.rschunks --json replace.json > /dev/null || fail "replace import"
python3 -c '
import json, sys
body = [m for m in json.load(open(sys.argv[1]))["meshes"] if m["mesh"] == "body"][0]
assert body["written"] == 1008 and body["kept"] == 0, body
' replace.json || fail "without --append every vertex is written"

# The weight depot: DIR/<asset>/<mesh>.rschunks; import reads them all, the newest chunk wins.
cp envelope.weights g.weights
"$cli" skin export g.yml --depot depot > depot.txt || fail "depot export"
[ -f depot/g/body.rschunks ] && [ -f depot/g/belt.rschunks ] || fail "depot files"
# All or nothing: a folder where one mesh's file goes fails the export before
# any file is replaced (either mesh first), and no temp file is left behind.
for blocked in belt body; do
    cp -r depot/g depot-before
    rm depot/g/$blocked.rschunks && mkdir depot/g/$blocked.rschunks
    sleep 1 # a later export time: every chunk file's bytes would differ
    if "$cli" skin export g.yml --depot depot > blocked.txt 2> blocked-errors.txt; then fail "a depot export over a folder succeeded"; fi
    grep -q "nothing was written: the weight depot keeps its previous files" blocked-errors.txt || fail "blocked depot message"
    rmdir depot/g/$blocked.rschunks
    for f in depot-before/*.rschunks; do
        [ "$(basename "$f")" = $blocked.rschunks ] || cmp -s "$f" depot/g/"$(basename "$f")" || fail "a failed depot export replaced $(basename "$f")"
    done
    [ -z "$(ls -A depot/g | grep '\.tmp$' || true)" ] || fail "a failed depot export left temp files: $(ls -A depot/g)"
    rm -rf depot/g && mv depot-before depot/g
done
cp closest.rschunks depot/g/old-body.rschunks
sleep 1
"$cli" skin export g.yml --depot depot --mesh body > /dev/null
"$cli" skin import g.yml --depot depot --json depot.json > /dev/null 2> depotmerge.txt || fail "depot import"
grep -q "mesh 'body': the chunk exported .* replaces the one exported" depotmerge.txt || fail "depot merge warning"
cmp -s g.weights envelope.weights || fail "a depot round trip changed the weights"
if "$cli" skin import g.yml --depot depot --asset villain 2> noasset.txt; then fail "a missing asset imported"; fi
grep -q "the weight depot has no chunk file for asset 'villain'" noasset.txt || fail "missing asset message"

# skin transfer: a remeshed body file gets weights from the chunk file, as chunks.
"$cli" skin transfer all.rschunks remesh.obj -o remesh.rschunks --method neighbours --json transfer.json --progress > /dev/null 2> progress.txt || fail "transfer"
grep -q "transferring weights: 100%" progress.txt || fail "--progress"
python3 -c '
import json, sys
m = json.load(open(sys.argv[1]))["meshes"]
assert len(m) == 1 and m[0]["mesh"] == "body" and m[0]["route"] == "fallback" and m[0]["closestNeighbours"] == 2016, m
' transfer.json || fail "transfer report"
"$cli" skin info remesh.rschunks --limit 0 > remesh.txt
grep -q "exported vertices: 2016 (all)" remesh.txt && grep -q "influences: 6" remesh.txt || fail "transfer output"
if "$cli" skin transfer body.obj remesh.obj -o x.rschunks 2> model.txt; then fail "a model file as source"; fi
grep -q "body.obj: error: no mesh in the file is skinned" model.txt || fail "unskinned model source message"
set +e
"$cli" skin transfer all.rschunks remesh.obj -o x.fbx 2> fbx.txt; code=$?
set -e
[ "$code" = 2 ] || fail "-o x.fbx exited $code, not 2"
[ ! -e x.rschunks ] && [ ! -e x.fbx ] || fail "a failed transfer wrote a file"
echo "skin influences, selections, depot and transfer from the command line: ok"

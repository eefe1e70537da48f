#!/usr/bin/env bash
# rigsmith-cli skin export / import / info (issue 20) on a copy of the fitted
# human guide (tests/data/Skin/human): export then import is 1:1 and leaves the
# weights byte for byte; a posed guide exports both poses; a guide whose model
# is another mesh gets weights from the uber chunk; a merge keeps the newer
# chunk; damaged files, unknown meshes and bad options are errors (exit 1 or 2)
# that name the file and the byte. Exit 77 (skipped) without assimp-testmodels.
set -euo pipefail
cli=$1
guide=$2
human=/usr/share/assimp/models/Collada/human.zae
[ -f "$human" ] || { echo "skipped: $human is missing"; exit 77; }
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail() { echo "FAILED: $*"; for f in "$dir"/*.txt; do echo "--- $f"; cat "$f"; done; exit 1; }
cp "$guide" "$dir/guide.yml"
"$cli" skin bind "$dir/guide.yml" > /dev/null 2>&1
cp "$dir/guide.weights" "$dir/bound.weights"

# Export, then import: 1:1, the same weights bit for bit, a JSON report.
"$cli" skin export "$dir/guide.yml" -o "$dir/human.rschunks" > "$dir/export.txt" || fail "export"
grep -q "human-baseMesh: 53512 vertices, 87 influences, bind pose" "$dir/export.txt" || fail "export summary"
"$cli" skin import "$dir/guide.yml" "$dir/human.rschunks" --json "$dir/report.json" > "$dir/import.txt" || fail "import"
cmp -s "$dir/guide.weights" "$dir/bound.weights" || fail "a 1:1 import changed the weights"
python3 -c '
import json, sys
r = json.load(open(sys.argv[1]))
body = [m for m in r["meshes"] if m["mesh"] == "human-baseMesh"][0]
assert body["route"] == "one-to-one" and body["oneToOne"] == 53512, body
' "$dir/report.json" || fail "report"

# info: header, influences and vertices within the limits asked.
"$cli" skin info "$dir/human.rschunks" --mesh human-baseMesh --from 5 --limit 2 > "$dir/info.txt" || fail "info"
grep -q "exported vertices: 53512 (all)" "$dir/info.txt" || fail "info header"
grep -q "influences: 87 (5 to 6)" "$dir/info.txt" || fail "info influence range"
[ "$(grep -c '^    [0-9]* id ' "$dir/info.txt")" = 2 ] || fail "info vertex limit"

# A posed guide exports the test pose and the bind pose.
cp "$dir/guide.yml" "$dir/posed.yml"
cp "$dir/guide.weights" "$dir/posed.weights"
printf 'pose:\n  - {instance: 4, branch: L, node: ctrls.fk.0, values: {rz: 40}}\n' >> "$dir/posed.yml"
"$cli" skin export "$dir/posed.yml" -o "$dir/posed.rschunks" --mesh human-baseMesh > "$dir/posed.txt" || fail "posed export"
grep -q "test pose and bind pose" "$dir/posed.txt" || fail "posed export summary"
"$cli" skin info "$dir/posed.rschunks" --limit 0 > "$dir/posedinfo.txt"
grep -q "exported posed" "$dir/posedinfo.txt" || fail "posed info"
grep -q "^chunk 0: human-baseMesh" "$dir/posedinfo.txt" && ! grep -q "^chunk 1" "$dir/posedinfo.txt" || fail "--mesh export"

# A guide whose model is another mesh (a box): no name, count or order match, the uber chunk.
cp "$guide" "$dir/box.yml"
sed -i '/^models:/,/^instances:/{/^  - /d}' "$dir/box.yml"
"$cli" model add "$dir/box.yml" /usr/share/assimp/models/OBJ/box.obj > /dev/null
"$cli" skin import "$dir/box.yml" "$dir/human.rschunks" --method neighbours --normal-filter 0.75 --smooth 2 > "$dir/box.txt" || fail "box import"
grep -q "fallback from uber chunk (no name match, and no chunk has its vertex count and order)" "$dir/box.txt" || fail "box route"
test -s "$dir/box.weights" || fail "no box weights"

# Two files: the newer chunk of a name wins, with a warning naming both times.
sleep 1
"$cli" skin export "$dir/guide.yml" -o "$dir/newer.rschunks" --mesh human-highpolyeyesMesh > /dev/null
"$cli" skin import "$dir/guide.yml" "$dir/newer.rschunks" "$dir/human.rschunks" > /dev/null 2> "$dir/merge.txt" || fail "merge import"
grep -q "mesh 'human-highpolyeyesMesh': the chunk exported .* replaces the one exported" "$dir/merge.txt" || fail "merge warning"

# Damaged and truncated files, unknown meshes, bad options.
head -c 5000 "$dir/human.rschunks" > "$dir/cut.rschunks"
if "$cli" skin import "$dir/guide.yml" "$dir/cut.rschunks" 2> "$dir/cut.txt"; then fail "a truncated file was imported"; fi
grep -q "cut.rschunks: error: the skin chunk file is damaged or truncated: its checksum (the last 8 bytes, at byte 4992)" "$dir/cut.txt" || fail "truncation message"
cmp -s "$dir/guide.weights" "$dir/bound.weights" || fail "a failed import changed the weights"
if "$cli" skin info "$dir/guide.yml" 2> "$dir/foreign.txt"; then fail "a guide read as chunks"; fi
grep -q "not a Rigsmith skin chunk file" "$dir/foreign.txt" || fail "foreign message"
if "$cli" skin export "$dir/guide.yml" -o "$dir/x.rschunks" --mesh nose 2> "$dir/nose.txt"; then fail "an unknown mesh exported"; fi
grep -q "no mesh named 'nose'" "$dir/nose.txt" || fail "unknown mesh message"
set +e
"$cli" skin import "$dir/guide.yml" "$dir/human.rschunks" --method nearest 2> "$dir/usage.txt"; code=$?
set -e
[ "$code" = 2 ] || fail "a bad --method exited $code, not 2"
grep -q -- "--method is closest, neighbours or inpaint, not 'nearest'" "$dir/usage.txt" || fail "usage message"
# Inpainting from the command line: the box far from the human copies nothing near, so it keeps closest point.
"$cli" skin import "$dir/box.yml" "$dir/human.rschunks" --method inpaint --json - > "$dir/inpaint.txt" || fail "inpaint import"
grep -q '"inpainted": ' "$dir/inpaint.txt" || fail "inpaint report"
echo "skin chunks from the command line: ok"

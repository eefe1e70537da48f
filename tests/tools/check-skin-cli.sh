#!/usr/bin/env bash
# rigsmith-cli model add + skin bind on a copy of a sample guide: the model is
# kept relative to the guide, binding without --model binds it, the weights
# land beside the guide, adding it twice is refused, a guide without a model
# says how to add one.
set -euo pipefail
cli=$1
sample=$2
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
mkdir -p "$dir/models"
cp /usr/share/assimp/models/OBJ/box.obj "$dir/models/box.obj"
cp "$sample" "$dir/guide.yml"
"$cli" model add "$dir/guide.yml" "$dir/models/box.obj"
grep -q '^  - models/box.obj$' "$dir/guide.yml" || { echo "the model path is not kept relative"; exit 1; }
if "$cli" model add "$dir/guide.yml" "$dir/models/box.obj" 2>/dev/null; then echo "adding twice was accepted"; exit 1; fi
"$cli" skin bind "$dir/guide.yml" --max-influences 2 > "$dir/out.txt"
grep -q "bound to" "$dir/out.txt" || { cat "$dir/out.txt"; exit 1; }
test -s "$dir/guide.weights" || { echo "no weights beside the guide"; exit 1; }
# --json: the bones and each vertex's position and weights, for tools (compare-blender-weights). The biped has
# 95 skin bones: 87, and the legs' front chains (add_chains) on their 4 twist joints each.
"$cli" skin bind "$dir/guide.yml" -o "$dir/json.weights" --json "$dir/weights.json" > /dev/null
python3 -c '
import json, sys
d = json.load(open(sys.argv[1]))
assert len(d["bones"]) == 95, len(d["bones"])
m = d["meshes"][0]
assert len(m["positions"]) == len(m["weights"]) > 0
assert all(abs(sum(w for _, w in ws) - 1) < 1e-4 and all(0 <= b < 95 for b, _ in ws) for ws in m["weights"])
' "$dir/weights.json" || { echo "bad --json output"; exit 1; }
cp "$sample" "$dir/empty.yml"
if "$cli" skin bind "$dir/empty.yml" 2> "$dir/err.txt"; then echo "a guide without a model bound"; exit 1; fi
grep -q "model add" "$dir/err.txt" || { cat "$dir/err.txt"; exit 1; }
# A folder that cannot take the weights is refused before any binding.
if "$cli" skin bind "$dir/guide.yml" -o "$dir/missing/x.weights" > "$dir/out2.txt" 2> "$dir/err2.txt"; then echo "wrote into a missing folder"; exit 1; fi
grep -q "cannot write the weights there" "$dir/err2.txt" || { cat "$dir/err2.txt"; exit 1; }
if grep -q "bound to" "$dir/out2.txt"; then echo "bound before checking where the weights go"; exit 1; fi
# add --set with a value the option cannot take adds nothing.
cp "$dir/guide.yml" "$dir/before.yml"
if "$cli" add "$dir/guide.yml" arm.limb --under spine --set twist_upper=abc 2> "$dir/err3.txt"; then echo "a bad --set value was accepted"; exit 1; fi
cmp -s "$dir/guide.yml" "$dir/before.yml" || { echo "the guide changed"; exit 1; }
grep -q "was not taken" "$dir/err3.txt" || { cat "$dir/err3.txt"; exit 1; }
echo "ok"

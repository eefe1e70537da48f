#!/usr/bin/env bash
# Rigsmith's automatic weights against Blender's on the same character and the
# same joints (issue 19). Not a ctest: Blender is slow. Prints the share of
# vertices whose dominant joint agrees (body, and every mesh).
# usage: tests/tools/compare-blender-weights.sh RIGSMITH_CLI [GUIDE] [OUT_DIR]
#   GUIDE defaults to tests/data/Skin/human/guide.yml (the biped fitted to the
#   human of assimp-testmodels, which names the model to bind); OUT_DIR keeps
#   the weights, the JSON and Blender's report (default: a temporary folder).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
cli=$1
guide=${2:-$here/../data/Skin/human/guide.yml}
out=${3:-}
if [[ -z $out ]]; then
  out=$(mktemp -d)
  trap 'rm -rf "$out"' EXIT
fi
mkdir -p "$out"
command -v blender > /dev/null || { echo "blender is not installed (apt-get install blender)"; exit 2; }

# Our weights, with the bones and vertices as JSON.
"$cli" skin bind "$guide" -o "$out/rigsmith.weights" --json "$out/rigsmith.json" 2> "$out/bind.log"
# The skeleton as exported, for reference (the Blender armature is built from the JSON's bones).
"$cli" build "$guide" -o "$out/rig.glb" --reference "$out/rig.json" > "$out/build.log" 2>&1 || { cat "$out/build.log"; exit 1; }

# The model the guide names; Blender's Collada importer cannot read a zipped .zae.
model=$(sed -n '/^models:/{n;s/^  - //p}' "$guide")
[[ $model = /* ]] || model=$(dirname "$guide")/$model
case $model in
  *.zae) unzip -o -q "$model" -d "$out/model"; model=$(ls "$out"/model/*.dae | head -1) ;;
esac

blender -b --factory-startup --python "$here/compare-blender-weights.py" -- "$model" "$out/rigsmith.json" "$out/report.json" \
  > "$out/blender.log" 2>&1 || { tail -20 "$out/blender.log"; exit 1; }
grep '^COMPARE' "$out/blender.log" | sed 's/^COMPARE //'

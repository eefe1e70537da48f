#!/usr/bin/env bash
# rigsmith-cli skin import / export options (issue 20 items 3, 4, 6), each on
# a generated character (a world and a spine, a cylinder body and a belt, bound
# by envelope) and shown to act in its direction: the closest neighbours'
# count and distance multiplier blend more source vertices as they grow; the
# inpainting distance and angle copy more as they grow; the smoothing
# threshold smooths nothing at 1; --max-influences 1 leaves one weight per
# vertex; --no-search skips the count-and-order match; --export-pose reads
# the chunk's posed points; --progress prints on stderr; export --bind-pose,
# --dual-quaternion and --neighbours change the chunks as their --json
# reports say. A bad value of any option is refused by name (exit 2).
set -euo pipefail
cli=$1
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail() { echo "FAILED: $*"; for f in "$dir"/*.txt; do echo "--- $f"; head -20 "$f"; done; exit 1; }
cd "$dir"
python3 - <<'PY'
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
with open("trunk.obj", "w") as f:   # the body's topology under another name
    cylinder("trunk", 0.15, 0.8, 1.5, 15, 12, f, 0)
PY
"$cli" new g.yml --name hero > /dev/null
"$cli" add g.yml world.character > /dev/null
"$cli" add g.yml spine.torso --under world --at 0,0.9,0 > /dev/null
"$cli" model add g.yml body.obj > /dev/null
"$cli" skin bind g.yml --method envelope > /dev/null 2>&1
"$cli" skin export g.yml -o all.rschunks > /dev/null || fail "export"
"$cli" skin info all.rschunks --mesh body --limit 100000 --json - > source.json || fail "info --json"
for model in remesh trunk; do
    sed '/^models:/,/^instances:/{/^  - /d}' g.yml > $model.yml
    "$cli" model add $model.yml $model.obj > /dev/null
done

# The remesh's weights, exported and read back by info --json.
rows() { "$cli" skin export remesh.yml -o "$1.rschunks" > /dev/null && "$cli" skin info "$1.rschunks" --limit 100000 --json - > "$1.json"; }
# The share of the remesh's vertices whose weights are a source vertex's, unblended.
copied() {
    python3 -c '
import json, sys
def sets(path):
    rows = json.load(open(path))["chunks"][0]["vertexRows"]
    return [frozenset((n, round(w, 4)) for n, w in r["weights"] if w > 0) for r in rows]
source, target = set(sets(sys.argv[1])), sets(sys.argv[2])
print(sum(t in source for t in target) / len(target))
' source.json "$1.json"
}
more() { python3 -c 'import sys; sys.exit(0 if float(sys.argv[1]) > float(sys.argv[2]) else 1)' "$1" "$2"; }
# A member of the first mesh of a --json report.
member() { python3 -c 'import json, sys; print(json.load(open(sys.argv[1]))["meshes"][0][sys.argv[2]])' "$1" "$2"; }

# Closest neighbours: one neighbour copies a source vertex everywhere; eight blend.
for n in 1 8; do
    "$cli" skin import remesh.yml all.rschunks --method neighbours --distance-multiplier 10 --neighbours $n --json n$n-report.json > /dev/null || fail "--neighbours $n"
    rows n$n
done
[ "$(copied n1)" = 1.0 ] || fail "--neighbours 1 copies each vertex's weights from one source vertex: $(copied n1)"
more "$(copied n1)" "$(copied n8)" || fail "--neighbours 8 blends: $(copied n8) copied"
grep -q '"neighbours": 8' n8-report.json || fail "--neighbours in the report"
# The multiplier: 1 takes only the nearest (and ties), 10 the eight within ten times its distance.
for m in 1 10; do
    "$cli" skin import remesh.yml all.rschunks --method neighbours --distance-multiplier $m --neighbours 8 > /dev/null || fail "--distance-multiplier $m"
    rows m$m
done
more "$(copied m1)" "$(copied m10)" || fail "--distance-multiplier 10 blends more than 1: $(copied m1) vs $(copied m10)"

# Inpainting: a copied closest point must be within the distance and angle; more is inpainted as they shrink.
"$cli" skin import remesh.yml all.rschunks --method inpaint --inpaint-distance 0.000001 --json near.json > /dev/null || fail "--inpaint-distance"
"$cli" skin import remesh.yml all.rschunks --method inpaint --inpaint-distance 1 --json far.json > /dev/null
more "$(member near.json inpainted)" "$(member far.json inpainted)" || fail "a smaller --inpaint-distance inpaints more"
[ "$(member far.json inpainted)" = 0 ] || fail "--inpaint-distance 1 (the whole body) copies every vertex"
"$cli" skin import remesh.yml all.rschunks --method inpaint --inpaint-angle 1 --json narrow.json > /dev/null || fail "--inpaint-angle"
"$cli" skin import remesh.yml all.rschunks --method inpaint --inpaint-angle 180 --json wide.json > /dev/null
more "$(member narrow.json inpainted)" "$(member wide.json inpainted)" || fail "a smaller --inpaint-angle inpaints more"

# Smoothing only where a neighbour's weights differ by more than the threshold.
"$cli" skin import remesh.yml all.rschunks --smooth 3 --smooth-threshold 0 --json smooth0.json > /dev/null || fail "--smooth-threshold 0"
"$cli" skin import remesh.yml all.rschunks --smooth 3 --smooth-threshold 1 --json smooth1.json > /dev/null || fail "--smooth-threshold 1"
[ "$(member smooth0.json smoothed)" -gt 0 ] && [ "$(member smooth1.json smoothed)" = 0 ] || fail "--smooth-threshold 1 smooths nothing, 0 smooths"

# At most N weights per vertex.
"$cli" skin import remesh.yml all.rschunks > /dev/null && rows unlimited
"$cli" skin import remesh.yml all.rschunks --max-influences 1 > /dev/null || fail "--max-influences 1"
rows one
influences() { python3 -c 'import json, sys; print(max(len(r["weights"]) for r in json.load(open(sys.argv[1]))["chunks"][0]["vertexRows"]))' "$1.json"; }
[ "$(influences unlimited)" -gt 1 ] && [ "$(influences one)" = 1 ] || fail "--max-influences 1 leaves one weight per vertex"

# No name match: the chunk of the same count and order loads 1:1, unless --no-search.
"$cli" skin import trunk.yml all.rschunks --json search.json > /dev/null || fail "search"
"$cli" skin import trunk.yml all.rschunks --no-search --json nosearch.json > /dev/null || fail "--no-search"
[ "$(member search.json route)" = one-to-one ] && [ "$(member nosearch.json route)" = fallback ] &&
    [ "$(member nosearch.json source)" = "uber chunk" ] || fail "--no-search falls back on the uber chunk"

# A chunk exported posed: the import reads its bind points, unless --export-pose.
cp g.yml posed.yml && cp g.weights posed.weights
printf 'pose:\n  - {instance: 2, node: ctrls.ik_chest, values: {rz: 60}}\n' >> posed.yml
"$cli" skin export posed.yml -o posed.rschunks --json posed-export.json > /dev/null 2>&1 || fail "posed export"
"$cli" skin export posed.yml -o bind.rschunks --bind-pose --json bind-export.json > /dev/null 2>&1 || fail "--bind-pose export"
python3 -c '
import json, sys
posed, bind = (json.load(open(p)) for p in sys.argv[1:3])
assert not posed["options"]["bindPose"] and all(not c["bindPose"] for c in posed["chunks"]), posed
assert bind["options"]["bindPose"] and all(c["bindPose"] for c in bind["chunks"]), bind
' posed-export.json bind-export.json || fail "--bind-pose exports bind-pose chunks of a posed guide"
"$cli" skin import remesh.yml all.rschunks > /dev/null && cp remesh.weights frombind.weights
"$cli" skin import remesh.yml posed.rschunks > /dev/null && cp remesh.weights predeformed.weights
"$cli" skin import remesh.yml posed.rschunks --export-pose --json exportpose.json > /dev/null || fail "--export-pose"
cmp -s frombind.weights predeformed.weights || fail "a posed chunk's bind points give the bind chunk's weights"
! cmp -s frombind.weights remesh.weights || fail "--export-pose reads the posed points"
grep -q '"preDeformed": false' exportpose.json || fail "--export-pose in the report"

# --dual-quaternion: the chunk's posed points by dual quaternion skinning, and it says so.
"$cli" skin export posed.yml -o dq.rschunks --dual-quaternion --mesh body > /dev/null 2>&1 || fail "--dual-quaternion export"
"$cli" skin export posed.yml -o linear.rschunks --mesh body > /dev/null 2>&1
for f in dq linear; do "$cli" skin info $f.rschunks --limit 100000 --json - > $f.json; done
python3 -c '
import json, math, sys
dq, linear = (json.load(open(p))["chunks"][0] for p in sys.argv[1:3])
assert dq["skinning"] == "dual-quaternion" and linear["skinning"] == "linear", (dq["skinning"], linear["skinning"])
moved = max(math.dist(a["at"], b["at"]) for a, b in zip(dq["vertexRows"], linear["vertexRows"]))
same = max(math.dist(a["bindAt"], b["bindAt"]) for a, b in zip(dq["vertexRows"], linear["vertexRows"]))
assert moved > 0.005 and same == 0, (moved, same)
' dq.json linear.json || fail "--dual-quaternion poses the points otherwise, from the same bind points"

# --neighbours N: the neighbours sampled per exported vertex.
"$cli" skin export g.yml -o x0.rschunks --neighbours 0 --json x0.json > /dev/null || fail "export --neighbours 0"
"$cli" skin export g.yml -o x1.rschunks --neighbours 1 --json x1.json > /dev/null || fail "export --neighbours 1"
python3 -c '
import json, sys
n0, n1, n4 = (json.load(open(p)) for p in sys.argv[1:4])
assert n0["options"]["neighbours"] == 0 and all(c["neighbours"] == 0 for c in n0["chunks"]), n0
per = lambda r: [c["neighbours"] / c["vertices"] for c in r["chunks"]]
assert all(0 < a <= 1 for a in per(n1)) and all(a < b for a, b in zip(per(n1), per(n4))), (per(n1), per(n4))
' x0.json x1.json posed-export.json || fail "export --neighbours samples at most N neighbours per vertex"

# --progress: percent on stderr, even when stderr is no terminal.
"$cli" skin import remesh.yml all.rschunks --progress > /dev/null 2> progress.txt || fail "--progress"
grep -q "^importing weights: 100%$" progress.txt || fail "--progress prints percent"

# --json -: stdout is the report alone (the lines for people go to stderr), for every command.
json_only() { "$@" 2> /dev/null | python3 -c 'import json, sys; json.load(sys.stdin)'; }
json_only "$cli" skin import remesh.yml all.rschunks --json - || fail "import --json - is JSON alone"
json_only "$cli" skin export g.yml -o stdout.rschunks --json - || fail "export --json - is JSON alone"
json_only "$cli" skin transfer all.rschunks remesh.obj -o stdout-transfer.rschunks --json - || fail "transfer --json - is JSON alone"
json_only "$cli" skin info all.rschunks --json - || fail "info --json - is JSON alone"
"$cli" skin export g.yml -o stdout.rschunks --json - 2> human.txt > /dev/null
grep -q "^skin chunks: stdout.rschunks$" human.txt || fail "the lines for people go to stderr"

# Bad values: refused by name, exit 2, nothing written.
cp remesh.weights before.weights
refused() { # COMMAND... -- MESSAGE
    local args=() message
    while [ "$1" != -- ]; do args+=("$1"); shift; done
    message=$2
    set +e
    "$cli" "${args[@]}" > /dev/null 2> refused.txt; local code=$?
    set -e
    [ "$code" = 2 ] || fail "${args[*]} exited $code, not 2"
    grep -qF -- "$message" refused.txt || fail "${args[*]}: no '$message' in: $(head -1 refused.txt)"
}
i=(skin import remesh.yml all.rschunks)
refused "${i[@]}" --distance-multiplier 0.5 -- "--distance-multiplier is a number from 1 to 1000, not '0.5'"
refused "${i[@]}" --neighbours 0 -- "--neighbours is a whole number from 1 to 32, not '0'"
refused "${i[@]}" --inpaint-distance -1 -- "--inpaint-distance is metres, at least 0 (0: 5% of the mesh's size), not '-1'"
refused "${i[@]}" --inpaint-angle 200 -- "--inpaint-angle is degrees from 0 to 180, not '200'"
refused "${i[@]}" --smooth-threshold 2 -- "--smooth-threshold is a weight difference from 0 to 1, not '2'"
refused "${i[@]}" --max-influences 17 -- "--max-influences is a whole number from 1 to 16, not '17'"
refused "${i[@]}" --no-search=yes -- "unexpected argument '--no-search=yes'"
refused "${i[@]}" --json "" -- "--json is a file name (or - for stdout), not ''"
refused skin export g.yml -o x.rschunks --neighbours 33 -- "--neighbours is a whole number from 0 to 32, not '33'"
refused skin export g.yml -o x.rschunks --bind-pose=no -- "unexpected argument '--bind-pose=no'"
refused skin export g.yml -o x.rschunks --json "" -- "--json is a file name (or - for stdout), not ''"
refused skin info all.rschunks --json "" -- "--json is a file name (or - for stdout), not ''"
cmp -s before.weights remesh.weights || fail "a refused import changed the weights"
[ ! -e x.rschunks ] || fail "a refused export wrote a file"
echo "skin import and export options from the command line: ok"

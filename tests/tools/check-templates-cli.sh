#!/usr/bin/env bash
# rigsmith-cli check-templates on a user folder with one good and one broken
# template: one line per good template, file:line:col diagnostics, exit 1.
set -uo pipefail
cli=$1
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
mkdir -p "$dir/extra/tail" "$dir/extra/broken"
cat > "$dir/extra/tail/template.yml" <<'YML'
name: tail
base: core.joints
structure:
  chain: /*
  tip: chain[-1]
ui:
  hooks:
    default: tip
    joint: chain[:-1]
YML
printf 'name: broken\nstructure:\n  a: b\n  b: a\n' > "$dir/extra/broken/template.yml"
output=$("$cli" check-templates "$dir")
status=$?
expected="extra.tail: structure [chain, tip] hooks [default, joint] opts 8
59 shapes
$dir/extra/broken/template.yml:3:3: error: structure.a: the tag refers to itself (a -> b -> a)"
if [ "$output" != "$expected" ]; then
  echo "unexpected output:"; echo "$output"; echo "expected:"; echo "$expected"; exit 1
fi
[ "$status" -eq 1 ] || { echo "exit status $status, expected 1"; exit 1; }
rm -rf "$dir/extra/broken"
"$cli" check-templates "$dir" > /dev/null || { echo "a clean folder must exit 0"; exit 1; }
echo "check-templates OK"

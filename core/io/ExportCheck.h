#pragma once
// The validator exporters run before writing anything (issue 6): what engines
// reject or mangle, found on the export skeleton, each problem naming its node
// (Diagnostic::subject = the rig node, so the editor can select it).
//  - errors: more or fewer than one root; a joint with non-uniform scale, shear
//    or a mirrored (negative) bind matrix; a bind matrix that cannot be
//    inverted; duplicate names, also when they differ only by case (FBX and
//    Unreal compare names case-insensitively); names that are not engine-safe
//    (letters, digits, '_', not starting with a digit, not empty).
//  - safe fixes: renames that make every name engine-safe and unique; exporters
//    apply them only when asked. Scale and shear have no safe fix: they change
//    the rig, so the rigger fixes the guide.
#include "base/Diagnostic.h"
#include "model/Skeleton.h"

#include <map>
#include <string>

namespace rs::io {

struct ExportCheck {
    Diagnostics problems;
    std::map<int, std::string> renames; // skeleton joint index -> safe unique name
    bool hasErrors() const { return rs::hasErrors(problems); }
};

ExportCheck checkSkeleton(const model::Rig& rig, const model::Skeleton& skeleton);
// The skeleton with the check's renames applied.
model::Skeleton applyRenames(model::Skeleton skeleton, const ExportCheck& check);
bool isEngineSafeName(const std::string& name);

} // namespace rs::io

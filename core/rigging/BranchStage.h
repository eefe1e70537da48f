#pragma once
// Branches (`branches: [L, R]`): before anything is built, every branched
// instance (and everything hanging below it) is copied once per branch into an
// expanded guide. The first branch keeps the authored guide; the second of a
// mirror pair (L/R, l/r, ex/in, ext/int: x; up/dn: y; ft/bk: z, or the `sym`
// option) is mirrored across the plane. Branches nest and multiply: ids
// compose (`arm.L`, `quad.A.L`), suffixes too (`_L`, `_A_L`).
#include "base/Diagnostic.h"
#include "model/GuideDocument.h"
#include "templates/TemplateRegistry.h"

#include <string>
#include <unordered_map>

namespace rs::rigging {

struct BranchCopy {
    model::InstanceId original = model::kNoId; // the authored instance
    model::InstanceId twin = model::kNoId;     // the unmirrored copy of the same instance
    std::string baseName;                      // authored name, "arm"
    std::string id;                            // ".L" ("" when not branched)

    std::string branch() const { return id.empty() ? id : id.substr(1); } // "L", "A.L", ""
    CopyKey key() const { return {original, branch()}; }
    std::string suffix;                        // "_L"
    bool flip = false;                         // odd number of mirrored branches
    Mat4 mirror{1.0};                          // reflection applied to the authored guide (diagonal +-1)
};

struct ExpandedGuide {
    model::GuideDocument document;                                // copies named "arm.L", parents first
    std::unordered_map<model::InstanceId, BranchCopy> copies;     // by expanded instance id
    std::unordered_map<model::JointId, model::JointId> original;  // expanded joint -> authored joint
};

ExpandedGuide expandBranches(const model::GuideDocument& guide, const templates::TemplateRegistry& templates,
                             Diagnostics& diagnostics);

} // namespace rs::rigging

#pragma once
// Where the mirrored branch copies' guide joints will be (the `.R` side of an
// authored arm with `branches: [L, R]`), computed with the builder's own branch
// expansion so the viewport can draw them without knowing the builder.
#include "base/Math.h"
#include "model/GuideDocument.h"
#include "templates/TemplateRegistry.h"

#include <vector>

namespace rs::session {

// One guide joint of a mirrored copy, in world space (metres).
struct MirroredGuideJoint {
    model::InstanceId owner = model::kNoId; // the authored instance the copy comes from
    Vec3 position{0.0};
    Vec3 parentPosition{0.0};               // valid when hasParent
    bool hasParent = false;
};

// Joints of every mirrored copy (copies without a reflection are left out);
// branch problems are ignored here, the build reports them.
std::vector<MirroredGuideJoint> mirroredGuideJoints(const model::GuideDocument& guide,
                                                    const templates::TemplateRegistry& templates);

} // namespace rs::session

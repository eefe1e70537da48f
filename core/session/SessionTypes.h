#pragma once
// The small value types session::Session's guide and rig API speaks in: what
// is selected (Selection), the editor's mode, the pose tools, and the callback
// an explicit build reports its progress through. The character's types are
// in SessionCharacter.h.
#include "model/Rig.h"

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace rs::session {

struct Selection {
    model::InstanceId instance = model::kNoId;
    model::JointId joint = model::kNoId;           // the current guide joint (the gizmo's)
    std::vector<model::JointId> joints;            // every selected guide joint, `joint` among them
    model::RigNodeIndex node = model::kNoNode;     // the current controller (rig mode) or shape (guide mode)
    std::vector<model::RigNodeIndex> nodes;        // every selected controller, `node` among them
    std::vector<model::CurveCv> cvs;               // CV mode: selected CVs, all of `node`

    // An instance (and one of its guide joints), no controllers.
    static Selection ofInstance(model::InstanceId id, model::JointId joint = model::kNoId)
    {
        Selection s;
        s.instance = id;
        s.joint = joint;
        return s;
    }
    bool operator==(const Selection&) const = default;
};

enum class Mode { Guide, Rig };

// How far an explicit build is: the fraction done (0 to 1) and the stage (the
// same function type as rigging::BuildProgress, so the builder takes it as is).
using BuildProgress = std::function<void(double fraction, const std::string& stage)>;
// How the last build used what the one before it generated: instance
// copies replayed unchanged, and generated (an explicit build generates all).
struct BuildReuse {
    std::size_t replayed = 0;
    std::size_t generated = 0;
};
enum class PoseTool { ResetSelected, ResetAll, Mirror, Flip, IkToFk, FkToIk };

} // namespace rs::session

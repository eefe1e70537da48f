#pragma once
// "Missing influences: create" (issue 20 item 4, after Skinner): an imported
// chunk's weighted influence the rig does not have (skin/InfluenceMap.h rules
// 1-3 leave it unplaced) becomes a joint of the guide: a core.joints instance
// of one joint, hung under the guide joint of the skin joint its nearest
// matched ancestor lands on (or under another created one; the skeleton's
// root when no ancestor matches), placed at the influence's bind matrix, its
// skin joint named exactly as the influence (a tag name override, `names:
// {skin.0: sk_ear}`), so the next import of the same chunks matches it by name.
// Under a branched (mirrored) parent, one instance serves both sides: ear_L
// and ear_R missing under head_L / head_R make one instance whose copies are
// sk_ear_L and sk_ear_R.
//
// The plan is made on the current guide and rig (instance and joint ids fixed
// then); the session adds the instances in the same undo step as the weights,
// the CLI adds them to the guide it saves.
#include "base/Result.h"
#include "edit/History.h"
#include "model/GuideDocument.h"
#include "model/Rig.h"
#include "skin/InfluenceMap.h"
#include "skin/SkinBones.h"
#include "templates/TemplateRegistry.h"

#include <string>
#include <vector>

namespace rs::session {

struct CreatedInfluence {
    std::string influence;                     // the chunks' influence name
    model::InstanceId instance = model::kNoId; // in CreatedInfluences::instances
    NodeKey bone;                              // its skin joint (in the parent's branch copy)
    std::string boneName;                      // that skin joint's name once built
    std::string parent;                        // the skin joint it hangs under
};

struct CreatedInfluences {
    std::vector<CreatedInfluence> influences;
    std::vector<model::TemplateInstance> instances; // to add, parents first
    bool empty() const { return influences.empty(); }
};

// Plans the joints for `chunks`' missing influences under `influences` (its
// name map counts; `missing` is not read). Appends each created skin joint to
// `bones` and `names` (the rig's skin bones and their export names), so that
// skin::resolveInfluences with MissingInfluences::Stop then places every
// influence. A note per created joint goes to `notes`. Refused when the
// library has no core.joints or a parent skin joint has no guide joint.
Result<CreatedInfluences> planCreatedInfluences(const model::GuideDocument& guide, const model::Rig& rig,
                                                const templates::TemplateRegistry& templates, const std::vector<skin::SkinChunk>& chunks,
                                                const skin::InfluenceMapOptions& influences, std::vector<skin::SkinBone>& bones,
                                                std::vector<std::string>& names);

// Adds the planned instances through `history` (refused, after adding none,
// when the guide no longer has room for them as planned).
Status addCreatedInstances(edit::History& history, const CreatedInfluences& created);

// The rules that place every influence once the planned joints are among the
// bones: `influences` with Stop for what is still missing, and a created
// joint named otherwise than its influence (a side added) in the name map.
skin::InfluenceMapOptions rulesWithCreated(const skin::InfluenceMapOptions& influences, const CreatedInfluences& created);

// Marks the matches of created influences as How::Created.
void markCreated(skin::InfluenceResolution& resolution, const CreatedInfluences& created);

} // namespace rs::session

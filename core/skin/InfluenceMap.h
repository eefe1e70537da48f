#pragma once
// Which skin joint of the target rig each influence of imported skin chunks
// lands on (issue 20 item 4, Skinner's "missing influences"). Per chunk
// influence, in this order:
//
//   1. identity: a skin joint with the influence's NodeKey
//   2. name: a skin joint whose export name is the influence's name
//   3. the name map (always applied when given): influence name -> rig joint name
//   4. still missing, by the rigger's choice (MissingInfluences):
//      - Stop (default): an error per missing influence, naming it and the
//        meshes whose chunks weight it; nothing is imported.
//      - Map: as Stop; says the name map is the way (the map must be given).
//      - Create: "create under parent-matched names". The session and the
//        CLI add such an influence to the guide first, as a joint under its
//        matched parent (session/CreateInfluences.h), and resolve with Stop,
//        so nothing is missing here. Called with Create directly (no guide to
//        add a joint to), the influence is re-homed: its weights go to its
//        nearest ancestor in the chunk's hierarchy that rules 1-3 match (the
//        skeleton's root when none does), and a warning names each.
//
// An influence that carries no weight in its chunk is never missing: it is
// dropped (a chunk lists every skin joint of the rig it came from).
// A name map entry whose target is not a skin joint of the rig is an error;
// one whose source is not a missing influence gets a warning (not needed).
#include "base/Result.h"
#include "skin/SkinBones.h"
#include "skin/SkinChunk.h"

#include <map>
#include <string>
#include <vector>

namespace rs::skin {

enum class MissingInfluences { Stop, Map, Create };
const char* missingInfluencesName(MissingInfluences rule); // "stop", "map", "create"
std::optional<MissingInfluences> parseMissingInfluences(const std::string& name);

struct InfluenceMapOptions {
    MissingInfluences missing = MissingInfluences::Stop;
    std::map<std::string, std::string> names; // chunk influence name -> rig skin joint export name
};

// How one influence of the chunks was resolved (one entry per influence name
// and way, in the order first met). Unused: the rig does not have it and no
// chunk weights it; one the rig has counts by how it matched, weighted or not.
struct InfluenceMatch {
    enum class How { Identity, Name, Mapped, Created, Unused };
    How how = How::Identity;
    std::string name;                 // the influence's export name in the chunk
    std::string target;               // the rig joint's export name ("" when Unused)
    std::vector<std::string> meshes;  // chunks (mesh names) that weight it
};

struct InfluenceResolution {
    // Per chunk, per chunk influence: the bone it lands on, -1 (Unused: no weight).
    std::vector<std::vector<std::int32_t>> target;
    std::vector<InfluenceMatch> matches;
    std::size_t count(InfluenceMatch::How how) const;
};

// `boneNames[b]` is the export name of `bones[b]` (the rig node's name).
// Fails (every missing influence listed) under Stop / Map, or on a bad map entry.
Result<InfluenceResolution> resolveInfluences(const std::vector<SkinChunk>& chunks, const std::vector<SkinBone>& bones,
                                              const std::vector<std::string>& boneNames, const InfluenceMapOptions& options);

// The weighted influences rules 1-3 leave unplaced (what Stop would list),
// whatever options.missing says: one entry per name (`target` empty) with the
// meshes whose chunks weight it. Empty when every influence is placed or
// there is no bone.
std::vector<InfluenceMatch> missingInfluences(const std::vector<SkinChunk>& chunks, const std::vector<SkinBone>& bones,
                                              const std::vector<std::string>& boneNames, const InfluenceMapOptions& options);

// The chunks with their weights on `bones` (joints and parents the bones', in
// order; `joints` named after them): each influence's share moved to its
// target, shares landing on one bone added (order of first appearance). A
// chunk already on the bones is returned unchanged, bit for bit.
std::vector<SkinChunk> applyInfluences(std::vector<SkinChunk> chunks, const InfluenceResolution& resolution,
                                       const std::vector<SkinBone>& bones, const std::vector<std::string>& boneNames);

} // namespace rs::skin

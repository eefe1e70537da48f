#pragma once
// What an open guide's session holds of the character, and reads back without
// a command: the guide's models as the host's loader read them, their meshes
// paired with the guide's bindings and skinned on the built rig, the rig's
// skin bones and the palette meshes skin with, the painter's locks, vertex
// selection and copied weights, and the chunks kept for re-fitting.
// session::Session derives from it and is the only writer: its commands
// (SessionSkin.cpp, SessionPaint.cpp, SessionChunks.cpp, SessionRefit.cpp)
// keep these members in step with the document and the rig. Not thread-safe.
#include "base/Diagnostic.h"
#include "base/Identity.h"
#include "base/Math.h"
#include "model/Mesh.h"
#include "skin/SkinBones.h"
#include "skin/SkinChunk.h"
#include "skin/Surface.h"
#include "skin/Refit.h"

#include <cstdint>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace rs::session {

// One of the guide's models as the session holds it (SessionSkin.cpp).
struct LoadedModel {
    std::string path;                          // as in GuideDocument::models
    std::shared_ptr<const model::Model> model; // null when the file could not be read
    Diagnostics problems;                      // why not, or the reader's warnings
};

// One mesh of a loaded model and its skin weights on the built rig.
struct CharacterMesh {
    std::size_t model = 0; // into Session::models()
    std::size_t mesh = 0;  // into that model's meshes
    int binding = -1;      // into GuideDocument::bindings; -1: not bound
    bool changed = false;  // bound to another topology: its weights are kept, not applied
    // The binding's weights on Session::skinBones() (joint i is bone i; a
    // gone joint's share on its nearest surviving ancestor); null when the
    // mesh is not skinned (unbound, changed, or no rig).
    std::shared_ptr<const model::MeshWeights> weights;
    const model::Mesh& data(const std::vector<LoadedModel>& models) const { return models[model].model->meshes[mesh]; }
};

class SessionCharacter {
public:
    const std::vector<LoadedModel>& models() const { return m_models; }
    const std::vector<CharacterMesh>& characterMeshes() const { return m_characterMeshes; }
    // The built rig's skin bones (empty without a rig or skin joints).
    const std::vector<skin::SkinBone>& skinBones() const { return m_skinBones; }
    // Per skin bone: its posed world matrix times the inverse of its rest
    // (bind) matrix, following every evaluation: the palette meshes skin with.
    const std::vector<Mat4>& skinPalette() const { return m_skinPalette; }

    // The previous meshes' chunks a re-fit reads (Session::refitChangedMeshes)
    // and the options it imports with (skin::defaultRefitOptions until set).
    void setSavedChunks(std::vector<skin::SkinChunk> chunks) { m_savedChunks = std::move(chunks); }
    const std::vector<skin::SkinChunk>& savedChunks() const { return m_savedChunks; }
    const skin::TransferOptions& refitOptions() const { return m_refitOptions; }
    void setRefitOptions(skin::TransferOptions options) { m_refitOptions = std::move(options); }

protected:
    SessionCharacter() = default;
    ~SessionCharacter() = default;
    SessionCharacter(const SessionCharacter&) = delete;
    SessionCharacter& operator=(const SessionCharacter&) = delete;

    std::vector<LoadedModel> m_models;
    std::vector<CharacterMesh> m_characterMeshes;
    std::vector<skin::SkinBone> m_skinBones;
    std::vector<Mat4> m_bindInverse; // per skin bone
    std::vector<Mat4> m_skinPalette;
    std::string m_reportedCharacter; // the character messages last reported
    std::map<const model::Mesh*, std::shared_ptr<const skin::Surface>> m_surfaces; // welded, for the tools
    std::set<NodeKey> m_lockedJoints;
    std::map<std::size_t, std::vector<std::uint32_t>> m_selectedVertices;
    std::vector<std::pair<NodeKey, float>> m_copiedWeights;
    std::vector<skin::SkinChunk> m_savedChunks; // previous meshes, for re-fitting
    skin::TransferOptions m_refitOptions = skin::defaultRefitOptions();
};

} // namespace rs::session

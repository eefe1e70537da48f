#include "SceneCharacter.h"

#include <algorithm>
#include <deque>
#include <filesystem>
#include <limits>

namespace rs::viewport {

void CharacterWeights::follow(const session::Session& session, const edit::Change& change)
{
    using K = edit::ChangeKind;
    const auto& meshes = session.characterMeshes();
    const bool all = change.hasAny(K::Document | K::Models | K::Rig | K::Templates) ||
                     (change.has(K::Weights) && change.bindings.empty()) || m_weights.size() != meshes.size();
    if (all) {
        m_weights.clear();
        for (const session::CharacterMesh& mesh : meshes)
            m_weights.push_back(mesh.weights);
        return;
    }
    if (!change.has(K::Weights))
        return;
    for (std::size_t i = 0; i < meshes.size(); ++i) {
        const int binding = meshes[i].binding;
        if (binding >= 0 && std::find(change.bindings.begin(), change.bindings.end(), std::size_t(binding)) != change.bindings.end())
            m_weights[i] = meshes[i].weights;
    }
}

void addCharacter(Scene& scene, const session::Session& session, const CharacterWeights& weights, bool rigMode)
{
    const auto& models = session.models();
    const auto& meshes = session.characterMeshes();
    for (const Mat4& m : session.skinPalette())
        scene.palette.push_back(glm::mat4(m));
    for (std::size_t i = 0; i < meshes.size(); ++i) {
        const session::CharacterMesh& character = meshes[i];
        if (character.model >= models.size() || !models[character.model].model)
            continue;
        const session::LoadedModel& loaded = models[character.model];
        SceneMesh mesh;
        mesh.model = loaded.model;
        mesh.mesh = character.mesh;
        mesh.characterMesh = i;
        if (auto selected = session.selectedVertices().find(i); selected != session.selectedVertices().end())
            mesh.selectedVertices = selected->second;
        if (mesh.mesh >= mesh.model->meshes.size())
            continue;
        mesh.weights = i < weights.weights().size() ? weights.weights()[i] : character.weights;
        if (character.changed)
            mesh.weights.reset();
        const int material = mesh.data().material;
        if (material >= 0 && std::size_t(material) < mesh.model->materials.size()) {
            const model::Material& m = mesh.model->materials[std::size_t(material)];
            mesh.baseColor = glm::vec3(m.baseColor);
            if (m.image) { // embedded in the model file (GLB, FBX, .zae)
                mesh.texturePath = loaded.path + "#" + m.texture;
                mesh.textureImage = m.image;
            } else if (!m.texture.empty()) {
                const std::filesystem::path texture(m.texture);
                mesh.texturePath = (texture.is_absolute() ? texture : std::filesystem::path(loaded.path).parent_path() / texture)
                                       .lexically_normal()
                                       .string();
            }
        }
        mesh.skinned = rigMode && mesh.weights && mesh.weights->joints.size() <= scene.palette.size();
        scene.meshes.push_back(std::move(mesh));
    }
}

namespace {

// Every node `from` moves: the nodes below it and what constraints reading
// any of those write, transitively.
std::vector<bool> drivenBy(const model::Rig& rig, model::RigNodeIndex from)
{
    std::vector<bool> driven(rig.nodes.size(), false);
    const auto children = rig.childTable();
    std::vector<std::vector<std::size_t>> readers(rig.nodes.size());
    for (std::size_t c = 0; c < rig.constraints.size(); ++c)
        for (model::RigNodeIndex t : rig.constraints[c].targets)
            if (t < rig.nodes.size())
                readers[t].push_back(c);
    std::deque<model::RigNodeIndex> queue{from};
    driven[from] = true;
    auto visit = [&](model::RigNodeIndex n) {
        if (n < driven.size() && !driven[n]) {
            driven[n] = true;
            queue.push_back(n);
        }
    };
    while (!queue.empty()) {
        const model::RigNodeIndex n = queue.front();
        queue.pop_front();
        for (model::RigNodeIndex child : children[n])
            visit(child);
        for (std::size_t c : readers[n])
            for (model::RigNodeIndex d : rig.constraints[c].driven)
                visit(d);
    }
    return driven;
}

// The bone nearest to `position` among those `accept` takes; -1 when none.
template <class Accept>
int nearestBone(const std::vector<skin::SkinBone>& bones, const std::vector<Vec3>& positions, const Vec3& position, Accept accept)
{
    int best = -1;
    double bestDistance = std::numeric_limits<double>::max();
    for (std::size_t b = 0; b < bones.size(); ++b) {
        if (!accept(b))
            continue;
        const double d = glm::distance(positions[b], position);
        if (d < bestDistance) {
            bestDistance = d;
            best = int(b);
        }
    }
    return best;
}

} // namespace

int skinBoneFor(const session::Session& session, bool rigMode)
{
    const model::Rig* rig = session.rig();
    const auto& bones = session.skinBones();
    const session::Selection& selection = session.selection();
    if (!rig || bones.empty())
        return -1;
    const eval::EvalState* pose = rigMode ? session.evaluation() : nullptr;
    const bool posed = pose && pose->world.size() == rig->nodes.size();
    auto world = [&](model::RigNodeIndex n) { return translationOf(posed ? pose->worldMatrix(n) : rig->nodes[n].worldMatrix); };
    std::vector<Vec3> positions;
    for (const skin::SkinBone& bone : bones)
        positions.push_back(bone.node < rig->nodes.size() ? world(bone.node) : Vec3(0.0));
    auto valid = [&](std::size_t b) { return bones[b].node < rig->nodes.size(); };

    if (!rigMode) {
        const model::JointId joint = selection.joint;
        if (joint == model::kNoId || !session.document().joint(joint))
            return -1;
        for (std::size_t b = 0; b < bones.size(); ++b)
            if (valid(b) && rig->nodes[bones[b].node].guide == joint)
                return int(b);
        const model::TemplateInstance* owner = session.document().ownerOf(joint);
        const Vec3 at = translationOf(session.document().jointWorldMatrix(joint));
        return nearestBone(bones, positions, at, [&](std::size_t b) {
            return valid(b) && owner && rig->nodes[bones[b].node].owner == owner->id;
        });
    }
    const model::RigNodeIndex node = selection.node;
    if (node == model::kNoNode || node >= rig->nodes.size())
        return -1;
    for (std::size_t b = 0; b < bones.size(); ++b)
        if (bones[b].node == node)
            return int(b);
    const std::vector<bool> driven = drivenBy(*rig, node);
    const model::RigNode& selected = rig->nodes[node];
    if (selected.guide != model::kNoId)
        for (std::size_t b = 0; b < bones.size(); ++b)
            if (valid(b) && driven[bones[b].node] && rig->nodes[bones[b].node].guide == selected.guide)
                return int(b);
    const Vec3 at = world(node);
    const int drivenBone = nearestBone(bones, positions, at, [&](std::size_t b) { return valid(b) && driven[bones[b].node]; });
    if (drivenBone >= 0)
        return drivenBone;
    return nearestBone(bones, positions, at, [&](std::size_t b) { return valid(b) && rig->nodes[bones[b].node].owner == selected.owner; });
}

} // namespace rs::viewport

#pragma once
// The character in the Scene: the session's model meshes, their weights and
// the skin palette (Scene::meshes, Scene::palette), and which skin bone the
// selection stands for when weights are shown. No GL.
#include "Scene.h"

#include "session/Session.h"

#include <memory>
#include <vector>

namespace rs::viewport {

// The weights object drawn for each session.characterMeshes() entry. The
// session makes new weights objects for every mesh on any weight change; the
// renderer sends a mesh's weights again when the object changes, so this
// takes the session's new object only for the meshes a change names
// (ChangeKind::Weights with its bindings), and all of them on a new document,
// new models or a rebuilt rig.
class CharacterWeights {
public:
    void follow(const session::Session& session, const edit::Change& change);
    const std::vector<std::shared_ptr<const model::MeshWeights>>& weights() const { return m_weights; }

private:
    std::vector<std::shared_ptr<const model::MeshWeights>> m_weights;
};

// Adds every loaded model's meshes and the palette. A mesh is skinned (posed,
// opaque) in Rig mode when it is bound, unchanged, and the palette covers its
// joints; otherwise it is drawn see-through in the bind pose. Material: the
// mesh's base colour and texture, the texture path resolved against the model
// file's folder.
void addCharacter(Scene& scene, const session::Session& session, const CharacterWeights& weights, bool rigMode);

// The skin bone (into session.skinBones()) that stands for the selection when
// one joint's weights are shown; -1 when none does.
// Rig mode (selection.node, a rig node):
//   1. the node itself when it is a skin joint;
//   2. else, of the skin joints the node drives (the nodes below it in the
//      rig's hierarchy, and what any constraint reading one of those writes,
//      transitively), the one made from the same guide joint as the node;
//   3. else the nearest of those (posed positions) to the node;
//   4. else the nearest skin joint of the node's instance.
// Guide mode (selection.joint, a guide joint): the skin joint made from that
// guide joint, else the nearest skin joint of its instance (rest positions).
int skinBoneFor(const session::Session& session, bool rigMode);

} // namespace rs::viewport

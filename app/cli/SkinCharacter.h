#pragma once
// What the skin chunk commands read from a guide: its built rig and skin
// bones, its weight records (GUIDE.weights), its models, and each mesh paired
// with its record as the session pairs them (model::pairBindings: the n-th
// mesh of a name in a model with the n-th record of that model and name). Plus the small argument
// helpers those commands share.
#include "model/GuideDocument.h"
#include "model/Mesh.h"
#include "model/Rig.h"
#include "skin/SkinBones.h"
#include "skin/SkinChunk.h"
#include "templates/TemplateRegistry.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace rs::cli {

struct CharacterMesh {
    std::string model;                 // the model file (absolute, as in the guide)
    const model::Mesh* mesh = nullptr; // into Character::models
    int binding = -1;                  // into guide.bindings; -1: none
};

struct Character {
    std::shared_ptr<const templates::TemplateRegistry> templates; // the rig is built with
    model::GuideDocument guide;
    model::Rig rig;
    std::vector<skin::SkinBone> bones;
    std::vector<model::Model> models; // one per guide model
    std::vector<CharacterMesh> meshes;
};

// Prints every problem (stderr); nothing when the guide, its rig, its weights
// file or one of its models cannot be read, or it has no model.
std::optional<Character> loadCharacter(const std::string& guidePath);

// The meshes whose record fits them, as bound (skin::bindingChunk): what the
// guide keeps beside its weights (io::saveGuideChunks) to re-fit from. A
// record that does not fit its mesh keeps its chunk from `previous`.
std::vector<skin::SkinChunk> boundMeshChunks(const Character& character, const std::vector<skin::SkinChunk>& previous);

// Whether `weights` are on `bones` already (their keys and parents, in order):
// then they need no retargeting, which would renormalise them (bits change).
bool isOnBones(const model::MeshWeights& weights, const std::vector<skin::SkinBone>& bones);

// "rigsmith-cli COMMAND: MESSAGE" and the usage on stderr; returns 2.
int usageError(const std::string& command, const std::string& message);
bool parseCount(const std::string& text, int low, int high, int& out);
bool parseNumber(const std::string& text, double low, double high, double& out);
// Whether `path` may be written (checked before long work), with a message when not.
bool canWriteBeside(const std::string& path, const std::string& what);

} // namespace rs::cli

#pragma once
// The FBX writer's working state (internal to io/FbxExport.cpp, FbxScene.cpp
// and FbxAnimation.cpp): the Objects and Connections records being filled,
// object ids handed out in order from a fixed start (so the same scene always
// gets the same ids), the object counts per record kind for Definitions, and
// helpers for Properties70 entries.
#include "base/Math.h"
#include "io/ExportScene.h"
#include "io/FbxBinary.h"

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace rs::io::fbx {

// FBX time: ticks per second.
constexpr std::int64_t kTicksPerSecond = 46186158000;

class Document {
public:
    Node objects{"Objects"};
    Node connections{"Connections"};
    std::map<std::string, int> counts; // record kind -> objects written

    std::int64_t newId() { return m_nextId++; }
    // An object record `kind` ("Model", "Geometry"...) with its id, binary
    // name ("name\x00\x01Class") and type ("LimbNode", "Mesh", "" ...).
    Node& addObject(const std::string& kind, std::int64_t id, const std::string& name, const std::string& className,
                    const std::string& type);
    void connect(std::int64_t child, std::int64_t parent);                        // "OO"
    void connect(std::int64_t child, std::int64_t parent, const std::string& property); // "OP"

private:
    std::int64_t m_nextId = 1000000;
};

// Properties70 entries ("P": name, type, label, flags, values).
void propertyInt(Node& p70, const std::string& name, const std::string& type, std::int32_t value);
void propertyDouble(Node& p70, const std::string& name, double value, const std::string& flags = "");
void propertyVector(Node& p70, const std::string& name, const std::string& type, const Vec3& value,
                    const std::string& flags = "A");
void propertyTime(Node& p70, const std::string& name, std::int64_t ticks);
void propertyString(Node& p70, const std::string& name, const std::string& value, const std::string& flags = "");

// A 4x4 matrix as FBX stores it: 16 doubles, column by column (translation at 12..14).
std::vector<double> matrixArray(const Mat4& m);

// The ids of the models written for a scene's nodes (FbxScene.cpp), which the
// animation (FbxAnimation.cpp) targets.
struct ModelIds {
    std::vector<std::int64_t> joints, controllers;
    std::vector<std::int64_t> cameras, cameraAttributes; // Camera models and their NodeAttributes
};

// FBX cameras look down their +X with +Y up, the rig's down their -Z: a
// camera's model is its frame turned +90 degrees about its own Y (model X =
// frame -Z), which Blender's importer (MAT_CONVERT_CAMERA) and Assimp (look
// at +X) undo.
Quat fbxCameraTurn();

// Skeleton (LimbNode models and attributes), controllers (Null models with
// their user properties), meshes with geometry, skin, clusters, materials,
// textures and the bind pose. A texture's image is embedded (the Video's
// Content) when `embedTextures`, else only named (RelativeFilename: the file
// the writer puts beside the FBX, io/FbxExport.h).
ModelIds addSceneObjects(Document& doc, const ExportScene& scene, bool embedTextures = true);
// The file name each material's image has in the FBX (unique among the
// scene's, in material order); empty for a material without one.
std::vector<std::string> imageFileNames(const ExportScene& scene);
// One AnimationStack / AnimationLayer per clip with its curve nodes and
// curves, and the matching Take in `takes`.
void addClips(Document& doc, const ExportScene& scene, const ModelIds& ids, Node& takes);

} // namespace rs::io::fbx

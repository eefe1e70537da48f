#include "io/FbxExport.h"

#include "io/FbxRepair.h"
#include "io/AtomicFile.h"

#include <assimp/Exporter.hpp>
#include <assimp/scene.h>

#include <cstdio>
#include <filesystem>
#include <memory>
#include <set>

namespace rs::io {

namespace {

aiMatrix4x4 toAssimp(const Mat4& m)
{
    return aiMatrix4x4(ai_real(m[0][0]), ai_real(m[1][0]), ai_real(m[2][0]), ai_real(m[3][0]),
                       ai_real(m[0][1]), ai_real(m[1][1]), ai_real(m[2][1]), ai_real(m[3][1]),
                       ai_real(m[0][2]), ai_real(m[1][2]), ai_real(m[2][2]), ai_real(m[3][2]),
                       ai_real(m[0][3]), ai_real(m[1][3]), ai_real(m[2][3]), ai_real(m[3][3]));
}

template <typename T>
T** newArray(std::size_t count)
{
    auto** out = new T*[count];
    for (std::size_t i = 0; i < count; ++i)
        out[i] = nullptr;
    return out;
}

// Builds the node tree: joints (parents first), controllers, then meshes at the root.
void addNodes(aiScene& ai, const ExportScene& scene)
{
    const std::size_t joints = scene.joints.size(), controllers = scene.controllers.size();
    std::vector<aiNode*> nodes;
    std::vector<std::vector<aiNode*>> children(joints + controllers + 1); // last: the scene root
    for (std::size_t i = 0; i < joints; ++i) {
        const auto& j = scene.joints[i];
        nodes.push_back(new aiNode(j.name));
        nodes.back()->mTransformation = toAssimp(j.bindLocal); // bind pose at export (§6.2 rule 2)
        children[j.parent < 0 ? joints + controllers : std::size_t(j.parent)].push_back(nodes.back());
    }
    for (std::size_t i = 0; i < controllers; ++i) {
        const auto& c = scene.controllers[i];
        nodes.push_back(new aiNode(c.name));
        nodes.back()->mTransformation = toAssimp(c.poseLocal);
        children[c.parent < 0 ? joints + controllers : joints + std::size_t(c.parent)].push_back(nodes.back());
    }
    for (std::size_t m = 0; m < scene.meshes.size(); ++m) {
        auto* node = new aiNode(scene.meshes[m].name);
        node->mNumMeshes = 1;
        node->mMeshes = new unsigned int[1]{unsigned(m)};
        children.back().push_back(node);
    }
    nodes.push_back(ai.mRootNode);
    for (std::size_t i = 0; i < nodes.size(); ++i)
        if (!children[i].empty())
            nodes[i]->addChildren(unsigned(children[i].size()), children[i].data());
}

aiMesh* makeMesh(const SkinnedMesh& mesh, const ExportScene& scene)
{
    auto* out = new aiMesh;
    out->mName = mesh.name;
    out->mPrimitiveTypes = aiPrimitiveType_TRIANGLE;
    // The scene's materials, then the default one (see makeMaterials).
    const bool hasMaterial = mesh.material >= 0 && std::size_t(mesh.material) < scene.materials.size();
    out->mMaterialIndex = unsigned(hasMaterial ? std::size_t(mesh.material) : scene.materials.size());
    out->mNumVertices = unsigned(mesh.vertexCount());
    out->mVertices = new aiVector3D[mesh.vertexCount()];
    for (std::size_t v = 0; v < mesh.vertexCount(); ++v)
        out->mVertices[v] = aiVector3D(mesh.positions[v].x, mesh.positions[v].y, mesh.positions[v].z);
    if (!mesh.normals.empty()) {
        out->mNormals = new aiVector3D[mesh.vertexCount()];
        for (std::size_t v = 0; v < mesh.vertexCount(); ++v)
            out->mNormals[v] = aiVector3D(mesh.normals[v].x, mesh.normals[v].y, mesh.normals[v].z);
    }
    if (!mesh.uvs.empty()) { // FBX UVs are OpenGL's, as imported
        out->mNumUVComponents[0] = 2;
        out->mTextureCoords[0] = new aiVector3D[mesh.vertexCount()];
        for (std::size_t v = 0; v < mesh.vertexCount(); ++v)
            out->mTextureCoords[0][v] = aiVector3D(mesh.uvs[v].x, mesh.uvs[v].y, 0.f);
    }
    out->mNumFaces = unsigned(mesh.indices.size() / 3);
    out->mFaces = new aiFace[out->mNumFaces];
    for (std::size_t f = 0; f < out->mNumFaces; ++f) {
        out->mFaces[f].mNumIndices = 3;
        out->mFaces[f].mIndices = new unsigned int[3]{mesh.indices[3 * f], mesh.indices[3 * f + 1], mesh.indices[3 * f + 2]};
    }
    std::vector<std::vector<aiVertexWeight>> weights(scene.joints.size());
    for (std::size_t v = 0; v < mesh.vertexCount(); ++v)
        for (std::size_t k = 0; k < mesh.influenceCount(v); ++k) {
            const Influence& in = mesh.influencesOf(v)[k];
            weights[std::size_t(in.joint)].emplace_back(unsigned(v), in.weight);
        }
    out->mNumBones = unsigned(scene.joints.size());
    out->mBones = newArray<aiBone>(scene.joints.size());
    for (std::size_t j = 0; j < scene.joints.size(); ++j) {
        auto* bone = new aiBone;
        bone->mName = scene.joints[j].name;
        bone->mOffsetMatrix = toAssimp(glm::inverse(scene.joints[j].bindWorld)); // mesh node is identity
        bone->mNumWeights = unsigned(weights[j].size());
        if (!weights[j].empty()) {
            bone->mWeights = new aiVertexWeight[weights[j].size()];
            std::copy(weights[j].begin(), weights[j].end(), bone->mWeights);
        }
        out->mBones[j] = bone;
    }
    return out;
}

aiNodeAnim* makeChannel(const std::string& node, const ExportTrack& track, const std::vector<double>& times)
{
    auto* c = new aiNodeAnim;
    c->mNodeName = node;
    const unsigned n = unsigned(times.size());
    c->mNumPositionKeys = c->mNumRotationKeys = c->mNumScalingKeys = n;
    c->mPositionKeys = new aiVectorKey[n];
    c->mRotationKeys = new aiQuatKey[n];
    c->mScalingKeys = new aiVectorKey[n];
    for (unsigned k = 0; k < n; ++k) {
        const Vec3& t = track.translations[k];
        const Quat& q = track.rotations[k];
        const Vec3& s = track.scales[k];
        c->mPositionKeys[k] = aiVectorKey(times[k], aiVector3D(ai_real(t.x), ai_real(t.y), ai_real(t.z)));
        c->mRotationKeys[k] = aiQuatKey(times[k], aiQuaternion(ai_real(q.w), ai_real(q.x), ai_real(q.y), ai_real(q.z)));
        c->mScalingKeys[k] = aiVectorKey(times[k], aiVector3D(ai_real(s.x), ai_real(s.y), ai_real(s.z)));
    }
    return c;
}

aiAnimation* makeAnimation(const ExportClip& clip, const ExportScene& scene)
{
    auto* a = new aiAnimation;
    a->mName = clip.name;
    a->mTicksPerSecond = 1.0; // times in seconds (§6.2 rule 3: the exporter ignores ticks per second)
    a->mDuration = clip.times.empty() ? 0.0 : clip.times.back();
    a->mNumChannels = unsigned(clip.tracks.size());
    a->mChannels = newArray<aiNodeAnim>(clip.tracks.size());
    for (std::size_t i = 0; i < clip.tracks.size(); ++i) {
        const auto& track = clip.tracks[i];
        const std::string& name = track.controller ? scene.controllers[std::size_t(track.node)].name
                                                   : scene.joints[std::size_t(track.node)].name;
        a->mChannels[i] = makeChannel(name, track, clip.times);
    }
    return a;
}

// A one-key take holding the current pose, since FBX nodes must stay in bind pose.
std::optional<ExportClip> poseClip(const ExportScene& scene)
{
    bool posed = false;
    for (const auto& j : scene.joints)
        posed = posed || maxAbsDifference(j.poseLocal, j.bindLocal) > 1e-9;
    if (!posed)
        return std::nullopt;
    ExportClip clip;
    clip.name = "pose";
    clip.times = {0.0};
    for (std::size_t j = 0; j < scene.joints.size(); ++j) {
        ExportTrack track;
        track.node = int(j);
        Vec3 t, s;
        Quat r;
        decompose(scene.joints[j].poseLocal, t, r, s);
        track.translations = {t};
        track.rotations = {r};
        track.scales = {s};
        clip.tracks.push_back(std::move(track));
    }
    return clip;
}

void declareConvention(aiScene& ai, const Convention& convention)
{
    const double centimetresPerUnit = fbxUnitScaleFactor(convention.unitsPerMetre);
    const int up = convention.zUp ? 2 : 1, front = convention.zUp ? 1 : 2, frontSign = convention.zUp ? -1 : 1;
    ai.mMetaData = aiMetadata::Alloc(10);
    unsigned i = 0;
    ai.mMetaData->Set(i++, "UnitScaleFactor", centimetresPerUnit);
    ai.mMetaData->Set(i++, "OriginalUnitScaleFactor", centimetresPerUnit);
    ai.mMetaData->Set(i++, "UpAxis", int32_t(up));
    ai.mMetaData->Set(i++, "UpAxisSign", int32_t(1));
    ai.mMetaData->Set(i++, "FrontAxis", int32_t(front));
    ai.mMetaData->Set(i++, "FrontAxisSign", int32_t(frontSign));
    ai.mMetaData->Set(i++, "CoordAxis", int32_t(0));
    ai.mMetaData->Set(i++, "CoordAxisSign", int32_t(1));
    ai.mMetaData->Set(i++, "OriginalUpAxis", int32_t(up));
    ai.mMetaData->Set(i++, "OriginalUpAxisSign", int32_t(1));
}

// An image's name in the file: its file name, made unique among the scene's.
std::string uniqueImageName(const std::string& name, std::set<std::string>& taken)
{
    std::string out = name.empty() ? "texture.png" : name;
    for (int n = 2; !taken.insert(out).second; ++n)
        out = std::to_string(n) + "_" + name;
    return out;
}

// The scene's materials and a default one last (for meshes without one, and
// because Assimp wants at least one). Texture images are embedded: the
// material names the image by file name and an embedded texture of that name
// holds its bytes, which Assimp writes as the Video's Content, with the
// Texture's and the Video's file names equal (Blender pairs them by name).
void addMaterials(aiScene& ai, const ExportScene& scene)
{
    std::vector<std::pair<const ExportMaterial*, std::string>> textured;
    std::set<std::string> taken;
    ai.mNumMaterials = unsigned(scene.materials.size() + 1);
    ai.mMaterials = newArray<aiMaterial>(scene.materials.size() + 1);
    for (std::size_t i = 0; i <= scene.materials.size(); ++i) {
        auto* material = new aiMaterial;
        ai.mMaterials[i] = material;
        if (i == scene.materials.size()) {
            const aiString name("skin");
            material->AddProperty(&name, AI_MATKEY_NAME);
            continue;
        }
        const ExportMaterial& source = scene.materials[i];
        const aiString name(source.name);
        material->AddProperty(&name, AI_MATKEY_NAME);
        const aiColor3D colour(source.baseColor.x, source.baseColor.y, source.baseColor.z);
        material->AddProperty(&colour, 1, AI_MATKEY_COLOR_DIFFUSE);
        if (source.image.empty())
            continue;
        textured.emplace_back(&source, uniqueImageName(source.imageName, taken));
        const aiString texture(textured.back().second);
        material->AddProperty(&texture, AI_MATKEY_TEXTURE_DIFFUSE(0));
    }
    ai.mNumTextures = unsigned(textured.size());
    ai.mTextures = newArray<aiTexture>(textured.size());
    for (std::size_t t = 0; t < textured.size(); ++t) {
        const std::string& bytes = textured[t].first->image;
        auto* texture = new aiTexture;
        texture->mWidth = unsigned(bytes.size());
        texture->mHeight = 0; // compressed: mWidth bytes of a file
        const std::string extension = std::filesystem::path(textured[t].second).extension().string();
        std::snprintf(texture->achFormatHint, sizeof texture->achFormatHint, "%s",
                      extension.size() > 1 ? extension.substr(1, HINTMAXTEXTURELEN - 1).c_str() : "");
        texture->mFilename = textured[t].second;
        texture->pcData = new aiTexel[(bytes.size() + sizeof(aiTexel) - 1) / sizeof(aiTexel)]; // ~aiTexture delete[]s it
        std::copy(bytes.begin(), bytes.end(), reinterpret_cast<char*>(texture->pcData));
        ai.mTextures[t] = texture;
    }
}

std::unique_ptr<aiScene> makeScene(const ExportScene& scene, const Convention& convention)
{
    auto ai = std::make_unique<aiScene>();
    ai->mRootNode = new aiNode("RootNode");
    addMaterials(*ai, scene);
    ai->mNumMeshes = unsigned(scene.meshes.size());
    ai->mMeshes = newArray<aiMesh>(scene.meshes.size());
    for (std::size_t m = 0; m < scene.meshes.size(); ++m)
        ai->mMeshes[m] = makeMesh(scene.meshes[m], scene);
    addNodes(*ai, scene);
    std::vector<ExportClip> clips = scene.clips;
    if (auto pose = poseClip(scene))
        clips.insert(clips.begin(), *pose);
    ai->mNumAnimations = unsigned(clips.size());
    ai->mAnimations = newArray<aiAnimation>(clips.size());
    for (std::size_t a = 0; a < clips.size(); ++a)
        ai->mAnimations[a] = makeAnimation(clips[a], scene);
    declareConvention(*ai, convention);
    return ai;
}

} // namespace

Result<std::string> assimpFbxBytes(const ExportScene& scene, const Convention& convention)
{
    const auto ai = makeScene(scene, convention);
    Assimp::Exporter exporter;
    const aiExportDataBlob* blob = exporter.ExportToBlob(ai.get(), "fbx");
    if (!blob)
        return Result<std::string>::failure(
            makeError({}, std::string("Assimp's FBX exporter failed: ") + exporter.GetErrorString()));
    return std::string(static_cast<const char*>(blob->data), blob->size);
}

Diagnostics writeFbx(const ExportScene& scene, const std::string& path, const Convention& convention)
{
    Diagnostics report;
    if (scene.meshes.empty())
        report.push_back(makeWarning({path, 0, 0}, "FBX without a bound mesh: the joints are written as null nodes, "
                                                    "not a skeleton (engines import skeletons with their meshes)"));
    auto bytes = assimpFbxBytes(scene, convention);
    auto repaired = bytes ? repairFbxNullRecords(*bytes) : Result<std::string>::failure(bytes.takeDiagnostics());
    if (!repaired) {
        for (auto d : repaired.takeDiagnostics()) {
            d.where.file = path;
            report.push_back(d);
        }
        return report;
    }
    Diagnostics written = writeFileAtomically(path, repaired.take()).takeDiagnostics();
    report.insert(report.end(), written.begin(), written.end());
    return report;
}

} // namespace rs::io

#include "io/ModelImport.h"

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <map>

namespace rs::io {

namespace {

void fbxConvention(const aiScene& scene, double& metresPerUnit, bool& zUp)
{
    if (!scene.mMetaData)
        return;
    double unitScale = 0.0; // centimetres per unit
    if (scene.mMetaData->Get("UnitScaleFactor", unitScale) && unitScale > 0.0)
        metresPerUnit = metresPerFbxUnit(unitScale);
    else if (float f = 0.0f; scene.mMetaData->Get("UnitScaleFactor", f) && f > 0.0f)
        metresPerUnit = metresPerFbxUnit(f);
    int upAxis = 1;
    if (scene.mMetaData->Get("UpAxis", upAxis))
        zUp = upAxis == 2;
}

Mat4 toMat4(const aiMatrix4x4& m)
{
    Mat4 out(1.0);
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c)
            out[c][r] = m[r][c]; // Assimp is row-major
    return out;
}

struct Walker {
    const aiScene& scene;
    Mat4 convention; // file space -> guide space (unit and up axis)
    model::Model& out;
    std::map<std::string, int> jointIndex;
    std::map<const aiNode*, Mat4> nodeWorld;
    int unnamed = 0;

    void visit(const aiNode* node, const Mat4& parentWorld)
    {
        const Mat4 world = parentWorld * toMat4(node->mTransformation);
        nodeWorld[node] = world;
        for (unsigned k = 0; k < node->mNumMeshes; ++k)
            addMesh(*scene.mMeshes[node->mMeshes[k]], world, node->mName.C_Str());
        for (unsigned c = 0; c < node->mNumChildren; ++c)
            visit(node->mChildren[c], world);
    }

    void addMesh(const aiMesh& source, const Mat4& world, const std::string& nodeName)
    {
        if (!(source.mPrimitiveTypes & aiPrimitiveType_TRIANGLE))
            return;
        model::Mesh mesh;
        mesh.name = source.mName.length > 0 ? source.mName.C_Str() : nodeName;
        if (mesh.name.empty())
            mesh.name = "mesh" + std::to_string(++unnamed);
        const Mat4 toGuide = convention * world;
        const glm::dmat3 normalMatrix = glm::transpose(glm::inverse(glm::dmat3(toGuide)));
        mesh.positions.reserve(source.mNumVertices);
        for (unsigned v = 0; v < source.mNumVertices; ++v) {
            const aiVector3D& p = source.mVertices[v];
            mesh.positions.emplace_back(Vec3(toGuide * Vec4(p.x, p.y, p.z, 1.0)));
        }
        if (source.mNormals)
            for (unsigned v = 0; v < source.mNumVertices; ++v) {
                const aiVector3D& n = source.mNormals[v];
                const Vec3 turned = normalMatrix * Vec3(n.x, n.y, n.z);
                const double length = glm::length(turned);
                mesh.normals.emplace_back(length > 0.0 ? turned / length : Vec3(0, 1, 0));
            }
        if (source.mTextureCoords[0])
            for (unsigned v = 0; v < source.mNumVertices; ++v)
                mesh.uvs.emplace_back(source.mTextureCoords[0][v].x, source.mTextureCoords[0][v].y);
        mesh.indices.reserve(std::size_t(source.mNumFaces) * 3);
        for (unsigned f = 0; f < source.mNumFaces; ++f)
            if (source.mFaces[f].mNumIndices == 3)
                for (unsigned k = 0; k < 3; ++k)
                    mesh.indices.push_back(source.mFaces[f].mIndices[k]);
        mesh.material = int(source.mMaterialIndex) < int(out.materials.size()) ? int(source.mMaterialIndex) : -1;
        if (source.mNumBones > 0)
            mesh.fileWeights = readWeights(source, world);
        if (!mesh.indices.empty())
            out.meshes.push_back(std::move(mesh));
    }

    // The file's skeleton and the mesh's weights, per Assimp vertex: the mesh
    // keeps Assimp's vertices one for one (no JoinIdenticalVertices; the
    // readers that split vertices per face corner copy the weights to each
    // copy), so a bone's vertex id is the mesh's vertex index. A bone's bind
    // world is the mesh's world times its inverse offset. Joint indices are
    // the order met here; linkJoints renumbers them.
    model::FileWeights readWeights(const aiMesh& source, const Mat4& world)
    {
        model::FileWeights weights;
        std::vector<std::vector<model::Influence>> perVertex(source.mNumVertices);
        for (unsigned b = 0; b < source.mNumBones; ++b) {
            const aiBone& bone = *source.mBones[b];
            const std::string name = bone.mName.C_Str();
            const Mat4 bindWorld = convention * world * glm::inverse(toMat4(bone.mOffsetMatrix)) * glm::inverse(convention);
            auto [it, added] = jointIndex.try_emplace(name, int(out.joints.size()));
            if (added)
                out.joints.push_back({name, -1, bindWorld});
            const auto joint = std::uint32_t(it->second);
            weights.bones.push_back({joint, bindWorld});
            for (unsigned w = 0; w < bone.mNumWeights; ++w) {
                const aiVertexWeight& share = bone.mWeights[w];
                if (share.mVertexId < source.mNumVertices && std::isfinite(share.mWeight) && share.mWeight > 0.0f)
                    addShare(perVertex[share.mVertexId], joint, share.mWeight);
            }
        }
        weights.offsets.reserve(perVertex.size() + 1);
        weights.offsets.push_back(0);
        for (auto& shares : perVertex) {
            normalise(shares);
            weights.influences.insert(weights.influences.end(), shares.begin(), shares.end());
            weights.offsets.push_back(std::uint32_t(weights.influences.size()));
        }
        return weights;
    }

    // Two bones of one name in a mesh (some FBX files) add their shares.
    static void addShare(std::vector<model::Influence>& shares, std::uint32_t joint, float weight)
    {
        for (model::Influence& i : shares)
            if (i.joint == joint) {
                i.weight += weight;
                return;
            }
        shares.push_back({joint, weight});
    }

    static void normalise(std::vector<model::Influence>& shares)
    {
        double sum = 0.0;
        for (const model::Influence& i : shares)
            sum += i.weight;
        for (model::Influence& i : shares)
            i.weight = float(i.weight / sum);
        std::stable_sort(shares.begin(), shares.end(), [](const model::Influence& a, const model::Influence& b) { return a.weight > b.weight; });
    }

    // Parents of the file's joints from the node tree, and parents-first order.
    void linkJoints()
    {
        std::vector<model::FileJoint> joints = out.joints;
        for (auto& joint : joints) {
            const aiNode* node = scene.mRootNode->FindNode(joint.name.c_str());
            for (const aiNode* up = node ? node->mParent : nullptr; up; up = up->mParent)
                if (auto it = jointIndex.find(up->mName.C_Str()); it != jointIndex.end()) {
                    joint.parent = it->second;
                    break;
                }
        }
        std::vector<int> order, placed(joints.size(), -1);
        std::function<void(int)> place = [&](int j) {
            if (placed[std::size_t(j)] >= 0)
                return;
            placed[std::size_t(j)] = -2;
            if (joints[std::size_t(j)].parent >= 0 && placed[std::size_t(joints[std::size_t(j)].parent)] != -2)
                place(joints[std::size_t(j)].parent);
            placed[std::size_t(j)] = int(order.size());
            order.push_back(j);
        };
        for (int j = 0; j < int(joints.size()); ++j)
            place(j);
        out.joints.clear();
        for (int j : order) {
            model::FileJoint joint = joints[std::size_t(j)];
            joint.parent = joint.parent >= 0 ? placed[std::size_t(joint.parent)] : -1;
            out.joints.push_back(joint);
        }
        for (model::Mesh& mesh : out.meshes)
            if (mesh.fileWeights) {
                for (auto& bone : mesh.fileWeights->bones)
                    bone.joint = std::uint32_t(placed[bone.joint]);
                for (auto& influence : mesh.fileWeights->influences)
                    influence.joint = std::uint32_t(placed[influence.joint]);
            }
    }
};

} // namespace

Result<model::Model> importModel(const std::string& path)
{
    const SourceLocation where{path, 0, 0};
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec))
        return Result<model::Model>::failure(makeError(where, "no such file"));
    Assimp::Importer importer;
    const aiScene* scene = importer.ReadFile(path, aiProcess_Triangulate | aiProcess_SortByPType | aiProcess_GenSmoothNormals);
    if (!scene || !scene->mRootNode)
        return Result<model::Model>::failure(makeError(where, std::string("cannot read the model: ") + importer.GetErrorString()));
    model::Model out;
    out.path = path;
    const std::string extension = std::filesystem::path(path).extension().string();
    if (extension == ".fbx" || extension == ".FBX")
        fbxConvention(*scene, out.metresPerUnit, out.zUp);
    else if (extension == ".blend")
        out.zUp = true; // Blender's world is Z-up and Assimp keeps it
    Mat4 convention = glm::scale(Mat4(1.0), Vec3(out.metresPerUnit));
    if (out.zUp)
        convention = convention * Mat4(Vec4(1, 0, 0, 0), Vec4(0, 0, -1, 0), Vec4(0, 1, 0, 0), Vec4(0, 0, 0, 1)); // (x, y, z) -> (x, z, -y)
    for (unsigned m = 0; m < scene->mNumMaterials; ++m) {
        const aiMaterial& source = *scene->mMaterials[m];
        model::Material material;
        aiString name;
        if (source.Get(AI_MATKEY_NAME, name) == AI_SUCCESS)
            material.name = name.C_Str();
        aiColor4D colour;
        if (source.Get(AI_MATKEY_BASE_COLOR, colour) == AI_SUCCESS || source.Get(AI_MATKEY_COLOR_DIFFUSE, colour) == AI_SUCCESS)
            material.baseColor = Vec3(colour.r, colour.g, colour.b);
        aiString texture;
        if (source.GetTexture(aiTextureType_BASE_COLOR, 0, &texture) == AI_SUCCESS ||
            source.GetTexture(aiTextureType_DIFFUSE, 0, &texture) == AI_SUCCESS)
            material.texture = texture.C_Str();
        // An embedded image: named "*N" (its index) or by the file name the material uses.
        for (unsigned t = 0; t < scene->mNumTextures && !material.texture.empty() && !material.image; ++t) {
            const aiTexture& image = *scene->mTextures[t];
            if (image.mHeight != 0 || !image.pcData || image.mWidth == 0)
                continue; // decoded texels, not a file's bytes
            const std::string file = image.mFilename.C_Str();
            const auto baseName = [](const std::string& p) { return p.substr(p.find_last_of("/\\") + 1); };
            if (material.texture == "*" + std::to_string(t) ||
                (!file.empty() && (file == material.texture || baseName(file) == baseName(material.texture))))
                material.image = std::make_shared<const std::string>(reinterpret_cast<const char*>(image.pcData), image.mWidth);
        }
        out.materials.push_back(std::move(material));
    }
    Walker walker{*scene, convention, out, {}, {}, 0};
    walker.visit(scene->mRootNode, Mat4(1.0));
    walker.linkJoints();
    if (out.meshes.empty())
        return Result<model::Model>::failure(makeError(where, "the file has no triangles"));
    for (const auto& mesh : out.meshes)
        for (const auto& p : mesh.positions)
            if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
                return Result<model::Model>::failure(makeError(where, "mesh '" + mesh.name + "' has a vertex that is not a finite number"));
    return out;
}

} // namespace rs::io

namespace rs::io {

Result<std::map<std::string, std::string>> readEmbeddedImages(const std::string& path)
{
    Assimp::Importer importer;
    // No post-processing: only the textures are wanted.
    const aiScene* scene = importer.ReadFile(path, 0);
    if (!scene)
        return Result<std::map<std::string, std::string>>::failure(
            makeError({path, 0, 0}, std::string("cannot read the model: ") + importer.GetErrorString()));
    std::map<std::string, std::string> images;
    for (unsigned t = 0; t < scene->mNumTextures; ++t) {
        const aiTexture& texture = *scene->mTextures[t];
        if (texture.mHeight != 0 || !texture.pcData)
            continue; // decoded texels, not a file's bytes
        std::string bytes(reinterpret_cast<const char*>(texture.pcData), texture.mWidth);
        images.emplace("*" + std::to_string(t), bytes);
        if (texture.mFilename.length > 0)
            images.emplace(texture.mFilename.C_Str(), std::move(bytes));
    }
    return images;
}

} // namespace rs::io

// Chunks from a model file's own skin weights: see skin/ModelChunks.h.
#include "skin/ModelChunks.h"

#include <set>

namespace rs::skin {

NodeKey fileJointKey(const std::string& name) { return NodeKey{kNoId, "file", name}; }

namespace {

// The file's skeleton as influences: keys, parents, names and matrices.
std::vector<ChunkJoint> chunkJoints(const model::Model& model, const model::FileWeights& weights, model::MeshWeights& out)
{
    std::vector<Mat4> bind(model.joints.size());
    for (std::size_t j = 0; j < model.joints.size(); ++j)
        bind[j] = model.joints[j].world;
    for (const model::FileWeights::Bone& bone : weights.bones)
        if (bone.joint < bind.size())
            bind[bone.joint] = bone.bindWorld;
    std::vector<ChunkJoint> joints;
    for (std::size_t j = 0; j < model.joints.size(); ++j) {
        const model::FileJoint& joint = model.joints[j];
        ChunkJoint c{fileJointKey(joint.name), joint.name, bind[j], bind[j], bind[j]};
        if (joint.parent >= 0)
            c.local = glm::inverse(bind[std::size_t(joint.parent)]) * bind[j];
        joints.push_back(std::move(c));
        out.joints.push_back(joints.back().key);
        out.parents.push_back(joint.parent);
    }
    return joints;
}

} // namespace

Result<std::vector<SkinChunk>> chunksFromModel(const model::Model& model, const ChunkExportOptions& options)
{
    using Out = Result<std::vector<SkinChunk>>;
    const SourceLocation where{model.path, 0, 0};
    std::vector<SkinChunk> chunks;
    std::set<std::string> names;
    for (const model::Mesh& mesh : model.meshes) {
        if (!mesh.fileWeights)
            continue;
        if (!names.insert(mesh.name).second)
            return Out::failure(makeError(where, "two skinned meshes are named '" + mesh.name + "': a chunk set holds one chunk per mesh name"));
        model::MeshWeights weights;
        std::vector<ChunkJoint> joints = chunkJoints(model, *mesh.fileWeights, weights);
        weights.offsets = mesh.fileWeights->offsets;
        weights.influences = mesh.fileWeights->influences;
        auto chunk = makeBindPoseChunk(mesh, weights, std::move(joints), model.path, options);
        if (!chunk)
            return Out::failure(chunk.takeDiagnostics());
        chunks.push_back(chunk.take());
    }
    if (chunks.empty())
        return Out::failure(makeError(where, "no mesh in the file is skinned (no per-vertex skin weights): nothing to transfer from"));
    return chunks;
}

} // namespace rs::skin

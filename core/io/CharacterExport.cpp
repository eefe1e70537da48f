#include "io/CharacterExport.h"

#include "io/ModelImport.h"
#include "io/YamlText.h"
#include "model/Skeleton.h"
#include "skin/Retarget.h"

#include <filesystem>
#include <map>
#include <optional>

namespace rs::io {

namespace {

std::string fileName(const std::string& path) { return std::filesystem::path(path).filename().string(); }

Diagnostic meshProblem(Severity severity, const std::string& modelPath, const std::string& mesh, const std::string& message)
{
    const std::string text = "mesh '" + mesh + "' of " + fileName(modelPath) + ": " + message;
    Diagnostic d = severity == Severity::Error ? makeError({modelPath, 0, 0}, text) : makeWarning({modelPath, 0, 0}, text);
    d.subject = Subject::ofMesh(mesh);
    return d;
}

// The mesh's geometry, without weights yet.
SkinnedMesh geometryOf(const model::Mesh& source, int material)
{
    SkinnedMesh out;
    out.name = source.name;
    out.positions = source.positions;
    out.normals.reserve(source.normals.size());
    for (const glm::vec3& n : source.normals) // glTF wants unit normals to float precision
        out.normals.push_back(glm::length(n) > 0.f ? glm::normalize(n) : glm::vec3(0, 1, 0));
    out.uvs = source.uvs;
    out.indices = source.indices;
    out.material = material;
    return out;
}

void weightOnRoot(SkinnedMesh& mesh)
{
    mesh.influences.assign(mesh.vertexCount(), Influence{0, 1.f});
    mesh.influenceStart.resize(mesh.vertexCount() + 1);
    for (std::size_t v = 0; v <= mesh.vertexCount(); ++v)
        mesh.influenceStart[v] = std::uint32_t(v);
}

// Weights on the skin bones (bone b = `bones[b]`) as influences on the export
// skeleton's joints.
bool setWeights(SkinnedMesh& mesh, const model::MeshWeights& weights, const std::vector<int>& jointOfBone)
{
    mesh.influenceStart.assign(1, 0);
    mesh.influences.clear();
    mesh.influences.reserve(weights.influences.size());
    for (std::size_t v = 0; v < weights.vertexCount(); ++v) {
        for (const model::Influence* in = weights.begin(v); in != weights.end(v); ++in) {
            if (in->joint >= jointOfBone.size() || jointOfBone[in->joint] < 0)
                return false;
            mesh.influences.push_back({jointOfBone[in->joint], in->weight});
        }
        mesh.influenceStart.push_back(std::uint32_t(mesh.influences.size()));
    }
    return true;
}

// A material's texture image: the file beside the model, else the image the
// model embeds under that name (the model's embedded images read once).
class TextureReader {
public:
    // Fills the material's image; a warning when it cannot.
    void fill(ExportMaterial& material, const std::string& modelPath, const std::string& texture, Diagnostics& problems)
    {
        std::error_code ec;
        const std::filesystem::path file = std::filesystem::path(modelPath).parent_path() / texture;
        material.imageName = fileName(texture);
        if (!texture.empty() && texture[0] != '*' && std::filesystem::is_regular_file(file, ec)) {
            if (auto bytes = readTextFile(file.lexically_normal().string())) {
                material.imagePath = std::filesystem::absolute(file).lexically_normal().string();
                material.image = bytes.take();
            }
        } else if (const auto* images = embedded(modelPath)) {
            if (auto it = images->find(texture); it != images->end())
                material.image = it->second;
        }
        if (material.image.empty()) {
            problems.push_back(makeWarning({modelPath, 0, 0}, "material '" + material.name + "': its texture " + texture +
                                                                  " is neither a file beside the model nor in it; exported without it"));
            material.imageName.clear();
            return;
        }
        if (material.imageName.empty() || material.imageName[0] == '*')
            material.imageName = material.name + imageExtension(material.image);
        material.mimeType = imageMimeType(material.image);
    }

private:
    static std::string imageExtension(const std::string& bytes)
    {
        const std::string mime = imageMimeType(bytes);
        return mime == "image/png" ? ".png" : mime == "image/jpeg" ? ".jpg" : "";
    }

    const std::map<std::string, std::string>* embedded(const std::string& modelPath)
    {
        auto it = m_embedded.find(modelPath);
        if (it == m_embedded.end()) {
            auto read = readEmbeddedImages(modelPath);
            it = m_embedded.emplace(modelPath, read ? read.take() : std::map<std::string, std::string>{}).first;
        }
        return &it->second;
    }

    std::map<std::string, std::map<std::string, std::string>> m_embedded;
};

// The export skeleton's joint index of each skin bone (by rig node).
Result<std::vector<int>> jointsOfBones(const model::Rig& rig, const std::vector<skin::SkinBone>& bones)
{
    auto skeleton = model::extractSkeleton(rig);
    if (!skeleton)
        return Result<std::vector<int>>::failure(skeleton.takeDiagnostics());
    std::map<model::RigNodeIndex, int> jointOfNode;
    for (std::size_t j = 0; j < skeleton->joints.size(); ++j)
        jointOfNode[skeleton->joints[j].node] = int(j);
    std::vector<int> out;
    for (const skin::SkinBone& bone : bones) {
        const auto it = jointOfNode.find(bone.node);
        out.push_back(it == jointOfNode.end() ? -1 : it->second);
    }
    return out;
}

struct Gatherer {
    const std::vector<model::MeshBinding>& bindings;
    const std::vector<skin::SkinBone>& bones;
    const std::vector<int>& jointOfBone;
    CharacterExport out;
    TextureReader textures;
    std::vector<bool> used;

    // Materials of one model into the export's list; returns their export indices.
    std::vector<int> addMaterials(const CharacterModel& m)
    {
        std::vector<int> index;
        for (const model::Material& source : m.model->materials) {
            ExportMaterial material;
            material.name = source.name.empty() ? "material" + std::to_string(out.materials.size()) : source.name;
            material.baseColor = glm::clamp(glm::vec3(source.baseColor), glm::vec3(0.f), glm::vec3(1.f));
            if (!source.texture.empty())
                textures.fill(material, m.path, source.texture, out.problems);
            index.push_back(int(out.materials.size()));
            out.materials.push_back(std::move(material));
        }
        return index;
    }

    // `b`: the mesh's record (model::pairBindings), -1 for none.
    void addMesh(const CharacterModel& m, const model::Mesh& source, int b, const std::vector<int>& materials)
    {
        const int material = source.material >= 0 && std::size_t(source.material) < materials.size() ? materials[std::size_t(source.material)] : -1;
        SkinnedMesh mesh = geometryOf(source, material);
        std::string problem;
        if (b < 0) {
            problem = "it has no skin weights; bind it";
        } else if (!model::bindingFits(bindings[std::size_t(b)], source)) {
            problem = "it changed since it was bound (" + std::to_string(bindings[std::size_t(b)].vertexCount) + " vertices then, " +
                      std::to_string(source.vertexCount()) + " now); bind it again";
        } else {
            auto retargeted = skin::retargetWeights(bindings[std::size_t(b)].weights, bones, source.name);
            out.problems.insert(out.problems.end(), retargeted.diagnostics().begin(), retargeted.diagnostics().end());
            if (!retargeted || !setWeights(mesh, *retargeted, jointOfBone))
                problem = "its weights do not fit the rig's skin joints; bind it again";
        }
        if (!problem.empty()) {
            out.problems.push_back(meshProblem(Severity::Error, m.path, source.name, problem + " (a forced export carries it rigid on the root joint)"));
            weightOnRoot(mesh);
        }
        out.meshes.push_back(std::move(mesh));
    }
};

} // namespace

std::string imageMimeType(const std::string& bytes)
{
    if (bytes.size() >= 8 && bytes.compare(0, 8, "\x89PNG\r\n\x1a\n") == 0)
        return "image/png";
    if (bytes.size() >= 3 && bytes.compare(0, 3, "\xff\xd8\xff") == 0)
        return "image/jpeg";
    return {};
}

CharacterExport characterExport(const model::Rig& rig, const std::vector<model::MeshBinding>& bindings,
                                const std::vector<CharacterModel>& models)
{
    if (models.empty())
        return {};
    auto bones = skin::skinBones(rig);
    auto joints = bones ? jointsOfBones(rig, *bones) : Result<std::vector<int>>::failure(bones.takeDiagnostics());
    if (!joints) {
        CharacterExport failed;
        failed.problems = joints.takeDiagnostics();
        return failed;
    }
    Gatherer g{bindings, *bones, *joints, {}, {}, std::vector<bool>(bindings.size(), false)};
    std::vector<std::string> paths;
    std::vector<const model::Model*> read;
    for (const CharacterModel& m : models) {
        paths.push_back(m.path);
        read.push_back(m.model);
    }
    const auto pairs = model::pairBindings(paths, read, bindings);
    for (std::size_t i = 0; i < models.size(); ++i) {
        const CharacterModel& m = models[i];
        if (!m.model) {
            g.out.problems.push_back(makeError({m.path, 0, 0}, "the guide's model " + fileName(m.path) +
                                                                    " could not be read; its meshes are not exported"));
            for (std::size_t b = 0; b < bindings.size(); ++b)
                g.used[b] = g.used[b] || bindings[b].model == m.path;
            continue;
        }
        const std::vector<int> materials = g.addMaterials(m);
        for (std::size_t k = 0; k < m.model->meshes.size(); ++k) {
            const int b = pairs[i][k];
            if (b >= 0)
                g.used[std::size_t(b)] = true;
            g.addMesh(m, m.model->meshes[k], b, materials);
        }
    }
    for (std::size_t b = 0; b < bindings.size(); ++b)
        if (!g.used[b])
            g.out.problems.push_back(meshProblem(Severity::Warning, bindings[b].model, bindings[b].mesh,
                                                 "its weights match no mesh of the guide's models; they are kept, not exported"));
    return std::move(g.out);
}

} // namespace rs::io

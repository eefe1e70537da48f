#include "cli/SkinCharacter.h"

#include "cli/Commands.h"
#include "io/AtomicFile.h"
#include "io/GuideFile.h"
#include "io/ModelImport.h"
#include "io/TemplateFolders.h"
#include "io/WeightsFile.h"
#include "rigging/RigBuilder.h"
#include "skin/Refit.h"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>

#include <unistd.h>

namespace rs::cli {

std::optional<Character> loadCharacter(const std::string& guidePath)
{
    Diagnostics templateDiagnostics;
    auto templates = io::loadDefaultTemplates(templateDiagnostics);
    auto guide = io::readGuideFile(guidePath);
    print(guide.diagnostics());
    if (!guide)
        return std::nullopt;
    Character c;
    c.templates = templates;
    c.guide = guide.take();
    const Status weights = io::loadGuideWeights(guidePath, c.guide);
    print(weights.diagnostics());
    if (weights.failed())
        return std::nullopt;
    c.rig = rigging::buildRig(c.guide, *templates);
    if (hasErrors(c.rig.diagnostics)) {
        print(c.rig.diagnostics);
        return std::nullopt;
    }
    auto bones = skin::skinBones(c.rig);
    if (!bones) {
        print(bones.diagnostics());
        return std::nullopt;
    }
    c.bones = bones.take();
    if (c.guide.models.empty()) {
        std::cerr << guidePath << ": error: the guide has no model; add one with 'rigsmith-cli model add " << guidePath << " FILE'\n";
        return std::nullopt;
    }
    c.models.reserve(c.guide.models.size()); // meshes point into it
    std::vector<const model::Model*> read;
    for (const std::string& path : c.guide.models) {
        auto model = io::importModel(path);
        print(model.diagnostics());
        if (!model)
            return std::nullopt;
        c.models.push_back(model.take());
        read.push_back(&c.models.back());
    }
    const auto pairs = model::pairBindings(c.guide.models, read, c.guide.bindings);
    for (std::size_t m = 0; m < c.models.size(); ++m)
        for (std::size_t k = 0; k < c.models[m].meshes.size(); ++k)
            c.meshes.push_back({c.guide.models[m], &c.models[m].meshes[k], pairs[m][k]});
    return c;
}

std::vector<skin::SkinChunk> boundMeshChunks(const Character& c, const std::vector<skin::SkinChunk>& previous)
{
    std::vector<skin::SkinChunk> out;
    std::vector<bool> covered(c.guide.bindings.size(), false);
    for (const CharacterMesh& m : c.meshes)
        if (m.binding >= 0 && model::bindingFits(c.guide.bindings[std::size_t(m.binding)], *m.mesh)) {
            covered[std::size_t(m.binding)] = true;
            out.push_back(skin::bindingChunk(c.guide.bindings[std::size_t(m.binding)], *m.mesh, &c.rig));
        }
    for (std::size_t b = 0; b < covered.size(); ++b)
        if (!covered[b])
            if (const skin::SkinChunk* kept = skin::previousChunk(previous, c.guide.bindings[b]))
                out.push_back(*kept);
    return out;
}

bool isOnBones(const model::MeshWeights& weights, const std::vector<skin::SkinBone>& bones)
{
    if (weights.joints.size() != bones.size() || weights.parents.size() != bones.size())
        return false;
    for (std::size_t b = 0; b < bones.size(); ++b)
        if (weights.joints[b] != bones[b].key || weights.parents[b] != bones[b].parent)
            return false;
    return true;
}

int usageError(const std::string& command, const std::string& message)
{
    std::cerr << "rigsmith-cli " << command << ": " << message << '\n' << usage();
    return 2;
}

bool parseCount(const std::string& text, int low, int high, int& out)
{
    char* end = nullptr;
    const long n = std::strtol(text.c_str(), &end, 10);
    if (text.empty() || *end != '\0' || n < low || n > high)
        return false;
    out = int(n);
    return true;
}

bool parseNumber(const std::string& text, double low, double high, double& out)
{
    char* end = nullptr;
    const double x = std::strtod(text.c_str(), &end);
    if (text.empty() || *end != '\0' || !std::isfinite(x) || x < low || x > high)
        return false;
    out = x;
    return true;
}

bool canWriteBeside(const std::string& path, const std::string& what)
{
    std::string target;
    const Status writable = io::resolveWriteTarget(path, target);
    if (writable.failed()) {
        print(writable.diagnostics());
        return false;
    }
    const auto folder = std::filesystem::absolute(target).parent_path();
    std::error_code ec;
    if (!std::filesystem::is_directory(folder, ec) || access(folder.c_str(), W_OK) != 0) {
        std::cerr << path << ": error: cannot write the " << what << " there: " << folder.string()
                  << " is not a folder this user may write to\n";
        return false;
    }
    return true;
}

} // namespace rs::cli

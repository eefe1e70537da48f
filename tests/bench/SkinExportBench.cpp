// Export of the bound human (issue 19): the human of Debian's assimp-testmodels
// (Collada/human.zae: body and eyes, 57,592 vertices, the eyes' PNG inside the
// .zae) bound by heat to the guide fitted to it (tests/data/Skin/human/guide.yml),
// exported by io::runExport as rigsmith-cli build -o does: gathering the meshes
// (weights retargeted to the rig), reading the texture (the .zae read again for
// its embedded image), the validator, and writing the file. Arg 0: .glb, 1: .fbx.
#include "io/ExportRequest.h"
#include "io/GuideFile.h"
#include "io/ModelImport.h"
#include "io/TemplateFolders.h"
#include "rigging/RigBuilder.h"
#include "skin/BindModels.h"

#include <benchmark/benchmark.h>

#include <filesystem>

using namespace rs;

namespace {

const std::string kSource = RIGSMITH_SOURCE_DIR;
const std::string kHuman = "/usr/share/assimp/models/Collada/human.zae";

struct BoundHuman {
    model::GuideDocument guide;
    model::Rig rig;
    std::shared_ptr<const model::Model> model;
    io::ExportCharacter character;
};

// Null when assimp-testmodels is not installed.
const BoundHuman* boundHuman()
{
    static const std::unique_ptr<BoundHuman> human = []() -> std::unique_ptr<BoundHuman> {
        auto imported = io::importModel(kHuman);
        if (!imported)
            return nullptr;
        auto h = std::make_unique<BoundHuman>();
        templates::TemplateRegistry templates;
        io::scanTemplates(templates, {kSource + "/templates"}, kSource + "/resources/icons");
        h->guide = io::readGuideFile(kSource + "/tests/data/Skin/human/guide.yml").take();
        h->rig = rigging::buildRig(h->guide, templates);
        h->model = std::make_shared<const model::Model>(imported.take());
        auto bindings = skin::bindModels({{kHuman, h->model}}, skin::skinBones(h->rig).take(), {});
        if (!bindings)
            return nullptr;
        h->character.bindings = bindings.take();
        h->character.models = {{kHuman, h->model.get()}};
        return h;
    }();
    return human.get();
}

void BM_ExportBoundHuman(benchmark::State& state)
{
    const BoundHuman* human = boundHuman();
    if (!human) {
        state.SkipWithError(("cannot read or bind " + kHuman + " (install assimp-testmodels)").c_str());
        return;
    }
    io::ExportRequest request;
    request.path = (std::filesystem::temp_directory_path() / (state.range(0) == 0 ? "bench-human.glb" : "bench-human.fbx")).string();
    for (auto _ : state) {
        const Diagnostics report = io::runExport(human->guide, human->rig, {}, request, {}, &human->character);
        if (hasErrors(report)) {
            state.SkipWithError(formatAll(report).c_str());
            break;
        }
    }
    state.SetLabel(state.range(0) == 0 ? "glb" : "fbx");
    state.counters["MB"] = double(std::filesystem::file_size(request.path)) / 1e6;
    std::filesystem::remove(request.path);
}
BENCHMARK(BM_ExportBoundHuman)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->Iterations(3);

} // namespace

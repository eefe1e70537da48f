// Core timings on the bundled samples: guide load/save, rig build, glTF export.
#include "build/RigBuilder.h"
#include "io/GltfExport.h"
#include "io/GuideFile.h"
#include "io/RigDump.h"

#include <benchmark/benchmark.h>

#include <filesystem>
#include <fstream>
#include <sstream>

using namespace rs;

namespace {

const std::string kSource = RIGSMITH_SOURCE_DIR;

std::string readText(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

const templates::TemplateRegistry& registry()
{
    static const auto r = [] {
        auto out = std::make_shared<templates::TemplateRegistry>();
        out->scan({kSource + "/templates"}, kSource + "/resources/icons");
        return out;
    }();
    return *r;
}

model::GuideDocument biped()
{
    return io::readGuideFile(kSource + "/resources/samples/biped.yml").take();
}

void BM_LoadBipedGuide(benchmark::State& state)
{
    const std::string text = readText(kSource + "/resources/samples/biped.yml");
    for (auto _ : state)
        benchmark::DoNotOptimize(io::readGuideText(text, "biped.yml"));
}
BENCHMARK(BM_LoadBipedGuide)->Unit(benchmark::kMicrosecond);

void BM_SaveBipedGuideText(benchmark::State& state)
{
    const auto doc = biped();
    for (auto _ : state)
        benchmark::DoNotOptimize(io::writeGuideText(doc));
}
BENCHMARK(BM_SaveBipedGuideText)->Unit(benchmark::kMicrosecond);

void BM_ScanTemplates(benchmark::State& state)
{
    for (auto _ : state) {
        templates::TemplateRegistry r;
        benchmark::DoNotOptimize(r.scan({kSource + "/templates"}, kSource + "/resources/icons"));
    }
}
BENCHMARK(BM_ScanTemplates)->Unit(benchmark::kMillisecond);

void BM_BuildBipedRig(benchmark::State& state)
{
    const auto doc = biped();
    const auto& templates = registry();
    for (auto _ : state)
        benchmark::DoNotOptimize(build::buildRig(doc, templates));
    state.counters["nodes"] = double(build::buildRig(doc, templates).nodes.size());
}
BENCHMARK(BM_BuildBipedRig)->Unit(benchmark::kMicrosecond);

void BM_DumpBipedRig(benchmark::State& state)
{
    const auto rig = build::buildRig(biped(), registry());
    for (auto _ : state)
        benchmark::DoNotOptimize(io::writeRigDump(rig));
}
BENCHMARK(BM_DumpBipedRig)->Unit(benchmark::kMicrosecond);

void BM_ExportBipedGlb(benchmark::State& state)
{
    const auto rig = build::buildRig(biped(), registry());
    const std::string path = (std::filesystem::temp_directory_path() / "rigsmith-bench-biped.glb").string();
    for (auto _ : state)
        benchmark::DoNotOptimize(io::exportGltf(rig, path));
}
BENCHMARK(BM_ExportBipedGlb)->Unit(benchmark::kMicrosecond);

} // namespace

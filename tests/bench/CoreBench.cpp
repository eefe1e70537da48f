// Core timings on the bundled samples: guide load/save, rig build, glTF export.
#include "build/RigBuilder.h"
#include "io/GltfExport.h"
#include "io/GuideFile.h"
#include "io/RigDump.h"

#include <benchmark/benchmark.h>

#include <algorithm>
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

// A library of state.range(0) templates (the golden-test manifests, which use every
// key, copied under distinct ids) plus the shipped shapes library, scanned cold.
void BM_ScanTemplateLibrary(benchmark::State& state)
{
    namespace fs = std::filesystem;
    const fs::path folder = fs::temp_directory_path() / ("rigsmith-bench-library-" + std::to_string(state.range(0)));
    fs::remove_all(folder);
    std::vector<fs::path> sources;
    for (const auto& entry : fs::directory_iterator(kSource + "/tests/data/ManifestReader"))
        sources.push_back(entry.path() / "template.yml");
    std::sort(sources.begin(), sources.end());
    for (long i = 0; i < state.range(0); ++i) {
        const fs::path module = folder / ("category" + std::to_string(i % 10)) / ("module" + std::to_string(i));
        fs::create_directories(module);
        fs::copy_file(sources[std::size_t(i) % sources.size()], module / "template.yml");
    }
    fs::create_directories(folder / "shapes");
    for (const auto& entry : fs::directory_iterator(kSource + "/templates/shapes"))
        if (entry.path().extension() == ".yml")
            fs::copy_file(entry.path(), folder / "shapes" / entry.path().filename());
    std::size_t templates = 0, shapes = 0;
    for (auto _ : state) {
        templates::TemplateRegistry r;
        benchmark::DoNotOptimize(r.scan({folder.string()}, kSource + "/resources/icons"));
        templates = r.all().size();
        shapes = r.shapes().size();
    }
    state.counters["templates"] = double(templates);
    state.counters["shapes"] = double(shapes);
    fs::remove_all(folder);
}
BENCHMARK(BM_ScanTemplateLibrary)->Arg(100)->Unit(benchmark::kMillisecond);

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

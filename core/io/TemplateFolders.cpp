#include "io/TemplateFolders.h"

#include "base/Paths.h"
#include "io/ManifestReader.h"
#include "io/ShapeFile.h"

#include <algorithm>
#include <atomic>
#include <filesystem>
#include <thread>

namespace rs::io {

using templates::Shape;
using templates::TemplateManifest;
using templates::TemplateRegistry;

namespace fs = std::filesystem;

namespace {

std::vector<fs::path> sortedSubdirectories(const fs::path& folder)
{
    std::vector<fs::path> out;
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(folder, ec))
        if (entry.is_directory())
            out.push_back(entry.path());
    std::sort(out.begin(), out.end());
    return out;
}

// One file to read. Files are parsed in parallel (yaml-cpp parses a few MB/s, so
// a large library is parse-bound) and merged in scan order, so the result and
// the order of diagnostics never depend on timing.
struct ScanJob {
    fs::path file;
    std::string category, module; // empty category: a shape file
    std::optional<TemplateManifest> manifest;
    std::optional<Shape> shape;
    Diagnostics diagnostics;

    void run()
    {
        if (category.empty()) {
            shape = readShapeFile(file.string(), diagnostics);
            return;
        }
        auto result = readManifest(file.string(), category, module);
        diagnostics = result.takeDiagnostics();
        if (result)
            manifest = result.take();
    }
};

void runAll(std::vector<ScanJob>& jobs)
{
    const unsigned threads = std::min<unsigned>(std::max(1u, std::thread::hardware_concurrency()), 8u);
    if (threads < 2 || jobs.size() < 8) {
        for (auto& job : jobs) job.run();
        return;
    }
    std::atomic<std::size_t> next{0};
    auto worker = [&] {
        for (std::size_t i = next++; i < jobs.size(); i = next++)
            jobs[i].run();
    };
    std::vector<std::thread> pool;
    for (unsigned t = 1; t < threads; ++t)
        pool.emplace_back(worker);
    worker();
    for (auto& t : pool)
        t.join();
}

} // namespace

Diagnostics scanTemplates(TemplateRegistry& registry, const std::vector<std::string>& folders,
                          const std::string& iconsDirectory)
{
    Diagnostics diagnostics;
    registry.reset(iconsDirectory);
    std::vector<ScanJob> jobs;
    for (const std::string& folder : folders) {
        std::error_code ec;
        if (!fs::is_directory(folder, ec)) {
            diagnostics.push_back(makeWarning({folder, 0, 0}, "template folder does not exist"));
            continue;
        }
        for (const fs::path& category : sortedSubdirectories(folder)) {
            const std::string categoryName = category.filename().string();
            if (categoryName == "shapes") {
                for (const std::string& file : shapeFilesIn(category.string()))
                    jobs.push_back({file, {}, {}, {}, {}, {}});
                continue;
            }
            for (const fs::path& module : sortedSubdirectories(category)) {
                const fs::path file = module / "template.yml";
                if (fs::exists(file, ec))
                    jobs.push_back({file, categoryName, module.filename().string(), {}, {}, {}});
            }
        }
    }
    runAll(jobs);
    for (ScanJob& job : jobs) {
        diagnostics.insert(diagnostics.end(), job.diagnostics.begin(), job.diagnostics.end());
        if (job.manifest)
            registry.add(std::move(*job.manifest));
        if (job.shape)
            registry.shapes().add(std::move(*job.shape));
    }
    const Diagnostics library = registry.crossCheck();
    diagnostics.insert(diagnostics.end(), library.begin(), library.end());
    return diagnostics;
}

std::shared_ptr<TemplateRegistry> loadDefaultTemplates(Diagnostics& diagnostics)
{
    auto registry = std::make_shared<TemplateRegistry>();
    diagnostics = scanTemplates(*registry, templateSearchPath(), iconsDirectory());
    return registry;
}

} // namespace rs::io

#include "templates/TemplateRegistry.h"

#include "base/Paths.h"
#include "templates/ManifestReader.h"

#include <algorithm>
#include <atomic>
#include <filesystem>
#include <thread>

namespace rs::templates {

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

const char* kFallbackIcon = "template";

} // namespace

namespace {

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

Diagnostics TemplateRegistry::scan(const std::vector<std::string>& folders, const std::string& iconsDirectory)
{
    Diagnostics diagnostics;
    m_manifests.clear();
    m_shapes.clear();
    m_iconsDirectory = iconsDirectory;
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
                for (const std::string& file : ShapeLibrary::filesIn(category.string()))
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
        if (job.manifest) {
            const std::string id = job.manifest->id;
            m_manifests[id] = std::move(*job.manifest);
        }
        if (job.shape)
            m_shapes.add(std::move(*job.shape));
    }
    // Cross-checks that need the whole library.
    std::error_code ec;
    for (const auto& [id, m] : m_manifests) {
        for (const ShapeSpec& s : m.shapes)
            if (!s.shape.empty() && !m_shapes.find(s.shape))
                diagnostics.push_back(makeWarning(s.where, "unknown shape '" + s.shape + "' in shapes." + s.key +
                                                               " (a circle is used)"));
        if (!m.icon.empty() && !fs::exists(fs::path(iconsDirectory) / (m.icon + ".svg"), ec))
            diagnostics.push_back(makeWarning(m.iconWhere, "icon '" + m.icon + "' not found in " + iconsDirectory +
                                                                  " (the default icon is used)"));
    }
    return diagnostics;
}

const TemplateManifest* TemplateRegistry::find(const std::string& id) const
{
    auto it = m_manifests.find(id);
    return it == m_manifests.end() ? nullptr : &it->second;
}

std::vector<const TemplateManifest*> TemplateRegistry::all() const
{
    std::vector<const TemplateManifest*> out;
    for (const auto& [id, m] : m_manifests)
        out.push_back(&m);
    return out;
}

std::vector<std::string> TemplateRegistry::categories() const
{
    std::vector<std::string> out;
    for (const auto& [id, m] : m_manifests)
        if (out.empty() || out.back() != m.category)
            out.push_back(m.category);
    return out;
}

std::string TemplateRegistry::iconPath(const TemplateManifest& manifest) const
{
    std::error_code ec;
    const fs::path icon = fs::path(m_iconsDirectory) / (manifest.icon + ".svg");
    if (!manifest.icon.empty() && fs::exists(icon, ec))
        return icon.string();
    return (fs::path(m_iconsDirectory) / (std::string(kFallbackIcon) + ".svg")).string();
}

std::shared_ptr<TemplateRegistry> TemplateRegistry::loadDefault(Diagnostics& diagnostics)
{
    auto registry = std::make_shared<TemplateRegistry>();
    diagnostics = registry->scan(templateSearchPath(), iconsDirectory());
    return registry;
}

} // namespace rs::templates

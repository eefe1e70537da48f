#include "cli/SkinChunkSupport.h"

#include "cli/Commands.h"
#include "io/SkinChunks.h"
#include "skin/Transfer.h"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <memory>
#include <set>
#include <sstream>

#include <pwd.h>
#include <unistd.h>

namespace rs::cli {

std::string userName()
{
    if (const char* user = std::getenv("USER"); user && *user)
        return user;
    if (const passwd* entry = getpwuid(getuid()))
        return entry->pw_name;
    return "";
}

std::int64_t nowMicroseconds()
{
    return std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::system_clock::now().time_since_epoch()).count();
}

namespace {

bool parseId(const std::string& text, std::uint32_t& out)
{
    if (text.empty() || text.size() > 10 || !std::all_of(text.begin(), text.end(), [](char c) { return c >= '0' && c <= '9'; }))
        return false;
    const unsigned long long n = std::stoull(text);
    out = std::uint32_t(n);
    return n <= 0xffffffffull;
}

} // namespace

bool parseVertexSelection(const std::string& text, VertexSelection& out)
{
    const std::size_t colon = text.rfind(':');
    if (colon == std::string::npos || colon == 0 || colon + 1 == text.size())
        return false;
    out.mesh = text.substr(0, colon);
    std::stringstream items(text.substr(colon + 1));
    for (std::string item; std::getline(items, item, ',');) {
        const std::size_t dash = item.find('-');
        std::uint32_t first = 0, last = 0;
        if (!parseId(item.substr(0, dash), first) || !parseId(dash == std::string::npos ? item : item.substr(dash + 1), last) || last < first)
            return false;
        out.ranges.emplace_back(first, last);
    }
    return !out.ranges.empty() && text.back() != ',';
}

Result<std::vector<std::uint32_t>> selectedVertices(const VertexSelection& selection, std::size_t vertexCount)
{
    std::vector<std::uint32_t> ids;
    for (const auto& [first, last] : selection.ranges) {
        if (last >= vertexCount)
            return Result<std::vector<std::uint32_t>>::refused("mesh '" + selection.mesh + "' has " + std::to_string(vertexCount) +
                                                               " vertices: vertex " + std::to_string(last) + " is not one of them");
        for (std::uint64_t v = first; v <= last; ++v)
            ids.push_back(std::uint32_t(v));
    }
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
    return ids;
}

std::string safeFileName(const std::string& name)
{
    std::string out;
    for (const char c : name.substr(0, 200))
        out += std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '_' || c == '-' ? c : '_';
    if (out.empty() || out[0] == '.')
        out.insert(out.begin(), '_');
    return out;
}

std::vector<std::string> depotPaths(const std::string& dir, const std::string& asset, const std::vector<std::string>& meshes)
{
    const std::filesystem::path folder = std::filesystem::path(dir) / safeFileName(asset);
    std::set<std::string> taken; // lower case: distinct on case-insensitive file systems too
    std::vector<std::string> paths;
    for (const std::string& mesh : meshes) {
        const std::string base = safeFileName(mesh);
        std::string name = base;
        auto lower = [](std::string s) {
            std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
            return s;
        };
        for (int n = 2; taken.count(lower(name)); ++n)
            name = base + "~" + std::to_string(n);
        taken.insert(lower(name));
        paths.push_back((folder / (name + ".rschunks")).string());
    }
    return paths;
}

Result<std::vector<std::string>> depotFiles(const std::string& dir, const std::string& asset)
{
    const std::filesystem::path folder = std::filesystem::path(dir) / safeFileName(asset);
    std::error_code ec;
    std::vector<std::string> files;
    for (std::filesystem::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec))
        if (it->path().extension() == ".rschunks" && it->is_regular_file(ec))
            files.push_back(it->path().string());
    std::sort(files.begin(), files.end());
    if (files.empty())
        return Result<std::vector<std::string>>::failure(
            makeError({folder.string(), 0, 0}, "the weight depot has no chunk file for asset '" + asset + "' (expected " +
                                                   (folder / "<mesh>.rschunks").string() + ")"));
    return files;
}

std::string assetOf(const std::string& guidePath)
{
    return std::filesystem::path(guidePath).stem().string();
}

std::function<bool(double)> progressPrinter(const std::string& what, bool forced)
{
    const bool terminal = isatty(STDERR_FILENO) != 0;
    if (!terminal && !forced)
        return {};
    using Clock = std::chrono::steady_clock;
    const auto start = Clock::now();
    auto last = std::make_shared<Clock::time_point>(start);
    auto shown = std::make_shared<int>(-1);
    return [=](double fraction) {
        const auto now = Clock::now();
        const int percent = std::clamp(int(fraction * 100.0), 0, 100);
        const bool quiet = (terminal && !forced && now - start < std::chrono::seconds(1)) || percent == *shown ||
                           (now - *last < std::chrono::milliseconds(200) && percent < 100);
        if (quiet || (!terminal && percent / 10 == *shown / 10))
            return true;
        *shown = percent;
        *last = now;
        std::cerr << (terminal ? "\r" : "") << what << ": " << percent << "%" << (terminal && percent < 100 ? "" : "\n") << std::flush;
        return true;
    };
}

std::optional<std::vector<skin::SkinChunk>> readChunkFiles(const std::vector<std::string>& files)
{
    std::vector<skin::SkinChunk> all;
    for (const std::string& file : files) {
        auto chunks = io::loadSkinChunkFile(file);
        print(chunks.diagnostics());
        if (!chunks)
            return std::nullopt;
        for (skin::SkinChunk& chunk : *chunks)
            all.push_back(std::move(chunk));
    }
    auto merged = skin::mergeChunks(std::move(all));
    print(merged.diagnostics());
    return merged.take();
}

} // namespace rs::cli

// The import decision tree of skin/Transfer.h, the merge of many files'
// chunks and the option checks. The fallback methods are TransferMethods.cpp.
#include "skin/Transfer.h"

#include <chrono>
#include <cmath>
#include <map>
#include <optional>

namespace rs::skin {

const char* transferMethodName(TransferMethod method)
{
    switch (method) {
    case TransferMethod::ClosestPoint: return "closest";
    case TransferMethod::ClosestNeighbours: return "neighbours";
    case TransferMethod::Inpainting: return "inpaint";
    }
    return "closest";
}

std::optional<TransferMethod> parseTransferMethod(const std::string& name)
{
    if (name == "closest" || name == "closest-point")
        return TransferMethod::ClosestPoint;
    if (name == "neighbours" || name == "neighbors" || name == "closest-neighbours")
        return TransferMethod::ClosestNeighbours;
    if (name == "inpaint" || name == "inpainting")
        return TransferMethod::Inpainting;
    return std::nullopt;
}

const char* importRouteName(ImportRoute route)
{
    switch (route) {
    case ImportRoute::OneToOne: return "one-to-one";
    case ImportRoute::SingleInfluence: return "single-influence";
    case ImportRoute::Fallback: return "fallback";
    }
    return "fallback";
}

Status validateTransferOptions(const TransferOptions& o)
{
    Diagnostics problems;
    auto refuse = [&](const std::string& what) { problems.push_back(makeError({}, what)); };
    if (!(o.neighbourDistanceMultiplier >= 1.0) || !std::isfinite(o.neighbourDistanceMultiplier))
        refuse("the nearest-neighbour distance multiplier must be a number of at least 1");
    if (o.neighbourCount < 1 || o.neighbourCount > 32)
        refuse("the number of neighbours must be from 1 to 32");
    if (!(o.normalTolerance >= -1.0 && o.normalTolerance <= 1.0))
        refuse("the normal tolerance must be from -1 to 1");
    if (o.smoothSteps < 0 || o.smoothSteps > 100)
        refuse("the smoothing steps must be from 0 to 100");
    if (!(o.weightDifferenceThreshold >= 0.0 && o.weightDifferenceThreshold <= 1.0))
        refuse("the weight difference threshold must be from 0 to 1");
    if (!(o.inpaintDistance >= 0.0) || !std::isfinite(o.inpaintDistance))
        refuse("the inpainting distance must be a number of metres, at least 0 (0: 5% of the mesh's size)");
    if (!(o.inpaintAngleDegrees >= 0.0 && o.inpaintAngleDegrees <= 180.0))
        refuse("the inpainting angle must be from 0 to 180 degrees");
    if (o.maxInfluences < 0 || o.maxInfluences > 16)
        refuse("the influence limit must be from 1 to 16 (0: the source's)");
    return problems.empty() ? Status() : Status::failure(std::move(problems));
}

Result<std::vector<SkinChunk>> mergeChunks(std::vector<SkinChunk> chunks)
{
    Diagnostics notes;
    std::map<std::string, std::size_t> byName; // mesh name -> index in `out`
    std::vector<SkinChunk> out;
    for (SkinChunk& c : chunks) {
        auto it = byName.find(c.mesh);
        if (it == byName.end()) {
            byName.emplace(c.mesh, out.size());
            out.push_back(std::move(c));
            continue;
        }
        SkinChunk& kept = out[it->second];
        const bool newer = c.exportedAtMicroseconds >= kept.exportedAtMicroseconds;
        SkinChunk& older = newer ? kept : c;
        SkinChunk& winner = newer ? c : kept;
        notes.push_back(makeWarning({}, "mesh '" + c.mesh + "': the chunk exported " + formatExportTime(winner.exportedAtMicroseconds) +
                                            " by " + (winner.user.empty() ? "(unknown)" : winner.user) + " replaces the one exported " +
                                            formatExportTime(older.exportedAtMicroseconds)));
        if (newer)
            kept = std::move(c);
    }
    return Result<std::vector<SkinChunk>>(std::move(out), std::move(notes));
}

namespace {

bool fits(const SkinChunk& c, const model::Mesh& mesh)
{
    return c.totalVertexCount == mesh.vertexCount() && c.fingerprint == model::topologyFingerprint(mesh);
}

// The one joint that carries weight in the chunk, if only one does.
std::optional<std::uint32_t> singleInfluence(const SkinChunk& c)
{
    std::optional<std::uint32_t> only;
    for (const model::Influence& i : c.weights.influences) {
        if (!(i.weight > 0.0f))
            continue;
        if (only && *only != i.joint)
            return std::nullopt;
        only = i.joint;
    }
    return only;
}

model::MeshWeights allOn(const SkinChunk& c, std::uint32_t joint, std::size_t vertices)
{
    model::MeshWeights out;
    out.joints = c.weights.joints;
    out.parents = c.weights.parents;
    out.offsets.resize(vertices + 1);
    for (std::size_t v = 0; v <= vertices; ++v)
        out.offsets[v] = std::uint32_t(v);
    out.influences.assign(vertices, {joint, 1.0f});
    return out;
}

// 1:1 by vertex id; vertices the chunk leaves out (a subset) by fallback on
// it, as a point set of their own (normals from the whole mesh, no smoothing).
Result<model::MeshWeights> oneToOne(const SkinChunk& c, const model::Mesh& mesh, const TransferOptions& options, MeshImportReport& report)
{
    const std::size_t n = mesh.vertexCount();
    std::vector<std::int64_t> from(n, -1);
    for (std::size_t i = 0; i < c.vertexIds.size(); ++i)
        from[c.vertexIds[i]] = std::int64_t(i);
    model::Mesh left;
    left.name = mesh.name;
    std::vector<std::uint32_t> leftIndex(n, 0), leftVertex; // mesh vertex -> left vertex and back
    if (c.vertexIds.size() < n) {
        const std::vector<glm::vec3> normals = mesh.normals.size() == n ? mesh.normals : vertexNormals(mesh);
        for (std::size_t v = 0; v < n; ++v)
            if (from[v] < 0) {
                leftIndex[v] = std::uint32_t(left.positions.size());
                leftVertex.push_back(std::uint32_t(v));
                left.positions.push_back(mesh.positions[v]);
                left.normals.push_back(normals[v]);
            }
    }
    model::MeshWeights rest;
    if (!left.positions.empty()) {
        auto source = TransferSource::fromChunk(c, options.usePreDeformed);
        if (!source)
            return Result<model::MeshWeights>::failure(source.takeDiagnostics());
        const std::size_t before = report.inpaintedVertices.size();
        auto transferred = transferWeights(*source, left, options, &report);
        if (!transferred)
            return transferred;
        rest = transferred.take();
        for (std::size_t k = before; k < report.inpaintedVertices.size(); ++k) // ids of `left` -> of the mesh (still ascending)
            report.inpaintedVertices[k] = leftVertex[report.inpaintedVertices[k]];
    }
    model::MeshWeights out;
    out.joints = c.weights.joints;
    out.parents = c.weights.parents;
    out.offsets.push_back(0);
    for (std::size_t v = 0; v < n; ++v) {
        if (from[v] >= 0)
            out.influences.insert(out.influences.end(), c.weights.begin(std::size_t(from[v])), c.weights.end(std::size_t(from[v])));
        else
            out.influences.insert(out.influences.end(), rest.begin(leftIndex[v]), rest.end(leftIndex[v]));
        out.offsets.push_back(std::uint32_t(out.influences.size()));
    }
    report.oneToOne = c.vertexIds.size();
    report.vertices = n;
    return out;
}

} // namespace

Result<std::vector<model::MeshWeights>> importChunks(const std::vector<SkinChunk>& chunks, const std::vector<const model::Mesh*>& targets,
                                                     const TransferOptions& options, std::vector<MeshImportReport>* reports)
{
    using Out = Result<std::vector<model::MeshWeights>>;
    const Status valid = validateTransferOptions(options);
    if (valid.failed())
        return Out::failure(valid.diagnostics());
    if (chunks.empty())
        return Out::failure(makeError({}, "no skin chunk to import"));
    std::optional<TransferSource> uber; // built when a mesh first needs it
    std::vector<model::MeshWeights> results;
    std::size_t totalVertices = 0, done = 0;
    for (const model::Mesh* mesh : targets)
        totalVertices += mesh->vertexCount();
    for (const model::Mesh* mesh : targets) {
        TransferOptions meshOptions = options; // progress over all meshes
        if (options.progress)
            meshOptions.progress = [&, mesh](double f) {
                return options.progress(double(done + f * double(mesh->vertexCount())) / double(std::max<std::size_t>(totalVertices, 1)));
            };
        MeshImportReport report;
        report.mesh = mesh->name;
        const auto start = std::chrono::steady_clock::now();
        const SkinChunk* named = nullptr;
        for (const SkinChunk& c : chunks)
            if (c.mesh == mesh->name && !options.forceUberChunk)
                named = &c;
        const SkinChunk* exact = nullptr;
        Result<model::MeshWeights> weights = Result<model::MeshWeights>::failure(Diagnostics{});
        if (named) {
            report.source = named->mesh;
            if (const auto joint = singleInfluence(*named)) {
                report.route = ImportRoute::SingleInfluence;
                report.why = "the chunk has a single influence";
                report.singleInfluence = report.vertices = mesh->vertexCount();
                weights = allOn(*named, *joint, mesh->vertexCount());
            } else if (fits(*named, *mesh)) {
                exact = named;
                report.why = "name, vertex count and order match";
            } else {
                report.why = "name matches; vertex count or order changed (" + std::to_string(named->totalVertexCount) + " -> " +
                             std::to_string(mesh->vertexCount()) + " vertices)";
            }
        } else if (options.searchByCountAndOrder && !options.forceUberChunk) {
            int matches = 0;
            for (const SkinChunk& c : chunks)
                if (fits(c, *mesh)) {
                    exact = &c;
                    ++matches;
                }
            if (matches != 1)
                exact = nullptr;
            report.why = matches == 1 ? "no name match; same vertex count and order as '" + exact->mesh + "'"
                         : matches > 1 ? "no name match; " + std::to_string(matches) + " chunks have its vertex count and order"
                                       : "no name match, and no chunk has its vertex count and order";
        } else {
            report.why = options.forceUberChunk ? "the uber chunk was asked for" : "no name match";
        }
        if (exact) {
            report.route = ImportRoute::OneToOne;
            report.source = exact->mesh;
            weights = oneToOne(*exact, *mesh, meshOptions, report);
        } else if (report.route != ImportRoute::SingleInfluence) {
            report.route = ImportRoute::Fallback;
            std::optional<TransferSource> own;
            if (named) {
                auto source = TransferSource::fromChunk(*named, options.usePreDeformed);
                if (!source)
                    return Out::failure(source.takeDiagnostics());
                own = source.take();
            } else if (!uber) {
                auto source = TransferSource::uber(chunks, options.usePreDeformed);
                if (!source)
                    return Out::failure(source.takeDiagnostics());
                uber = source.take();
            }
            if (!named)
                report.source = "uber chunk";
            weights = transferWeights(own ? *own : *uber, *mesh, meshOptions, &report);
        }
        if (!weights)
            return Out::failure(weights.takeDiagnostics());
        report.milliseconds = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        done += mesh->vertexCount();
        results.push_back(weights.take());
        if (reports)
            reports->push_back(std::move(report));
    }
    return results;
}

} // namespace rs::skin

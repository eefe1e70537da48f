// rigsmith-cli skin import: skin chunks (files, or a weight depot) onto a
// guide's meshes by the decision tree of skin/Transfer.h, their influences
// resolved onto the rig (skin/InfluenceMap.h), written only where the scope
// says (skin/ImportScope.h). Nothing is written when anything fails.
#include "cli/Commands.h"
#include "cli/SkinCharacter.h"
#include "cli/SkinChunkSupport.h"
#include "cli/SkinImportOptions.h"

#include "edit/History.h"
#include "io/AtomicFile.h"
#include "io/GuideFile.h"
#include "rigging/RigBuilder.h"
#include "session/CreateInfluences.h"
#include "io/InfluenceNameMap.h"
#include "io/WeightsFile.h"
#include "skin/ImportScope.h"
#include "skin/Retarget.h"

#include <algorithm>
#include <iostream>

namespace rs::cli {

namespace {

// One option of `skin import` with a value; `known` false: not one (or no value).
int parseImportOption(const std::vector<std::string>& args, std::size_t& i, ImportArguments& m, bool& known)
{
    const std::string& a = args[i];
    known = i + 1 < args.size();
    if (!known)
        return 0;
    const std::string& value = args[i + 1];
    auto bad = [&](const std::string& what) { return usageError("skin import", a + " is " + what + ", not '" + value + "'"); };
    if (a == "--mesh") {
        m.meshes.insert(value);
    } else if (a == "--vertices") {
        if (!parseVertexSelection(value, m.vertices.emplace_back()))
            return bad("MESH:RANGES, vertex ids and ranges such as body:0-99,120");
    } else if (a == "--missing") {
        const auto rule = skin::parseMissingInfluences(value);
        if (!rule)
            return bad("map, create or stop");
        m.influences.missing = *rule;
    } else if (a == "--map") {
        if (!io::parseInfluenceMapEntry(value, m.influences.names))
            return bad("OLD=NEW (an influence name in the chunks and a skin joint name of the rig)");
    } else if (a == "--name-map" || a == "--depot" || a == "--asset" || a == "--json") {
        if (value.empty())
            return bad(a == "--json" ? "a file name (or - for stdout)" : "a file or folder name");
        (a == "--name-map" ? m.nameMap : a == "--depot" ? m.depot : a == "--asset" ? m.asset : m.json) = value;
    } else {
        return parseTransferOption(args, i, m.options, known, "skin import");
    }
    ++i;
    return 0;
}

int parseImport(const std::vector<std::string>& args, ImportArguments& m)
{
    for (std::size_t i = 1; i < args.size(); ++i) {
        const std::string& a = args[i];
        bool known = false;
        if (const int usage = parseImportOption(args, i, m, known))
            return usage;
        if (known)
            continue;
        if (a == "--append")
            m.append = true;
        else if (a == "--progress")
            m.progress = true;
        else if (parseTransferFlag(a, m.options))
            continue;
        else if (!a.empty() && a[0] != '-')
            (m.guide.empty() ? m.guide : m.files.emplace_back()) = a;
        else
            return usageError("skin import", "unexpected argument '" + a + "'");
    }
    if (m.guide.empty() || (m.files.empty() && m.depot.empty()))
        return usageError("skin import", "expected GUIDE FILE... or GUIDE --depot DIR");
    if (m.influences.missing == skin::MissingInfluences::Map && m.influences.names.empty() && m.nameMap.empty())
        return usageError("skin import", "--missing map needs a name map: --map OLD=NEW or --name-map FILE");
    return 0;
}

// The chunk files and the depot's, read and merged; the name map file read.
std::optional<std::vector<skin::SkinChunk>> readSources(ImportArguments& m)
{
    if (!m.nameMap.empty()) {
        auto names = io::readInfluenceNameMap(m.nameMap);
        print(names.diagnostics());
        if (!names)
            return std::nullopt;
        for (const auto& [from, to] : *names)
            m.influences.names.emplace(from, to); // --map wins over the file
    }
    if (!m.depot.empty()) {
        auto files = depotFiles(m.depot, m.asset.empty() ? assetOf(m.guide) : m.asset);
        print(files.diagnostics());
        if (!files)
            return std::nullopt;
        m.files.insert(m.files.end(), files->begin(), files->end());
    }
    return readChunkFiles(m.files);
}

// The meshes imported onto, with their selected vertices; null on an error (printed).
std::optional<std::vector<ImportTarget>> importTargets(const ImportArguments& m, const Character& c)
{
    std::vector<ImportTarget> targets;
    bool ok = true;
    for (const CharacterMesh& mesh : c.meshes) {
        const bool named = m.meshes.count(mesh.mesh->name) > 0;
        ImportTarget t{mesh, {}, named || (m.meshes.empty() && m.vertices.empty()), 0, 0};
        for (const VertexSelection& s : m.vertices)
            if (s.mesh == mesh.mesh->name && !named) {
                auto ids = selectedVertices(s, mesh.mesh->vertexCount());
                print(ids.diagnostics());
                ok = ok && ids.ok();
                if (ids)
                    t.selection.insert(t.selection.end(), ids->begin(), ids->end());
            }
        std::sort(t.selection.begin(), t.selection.end());
        t.selection.erase(std::unique(t.selection.begin(), t.selection.end()), t.selection.end());
        if (t.whole || !t.selection.empty())
            targets.push_back(std::move(t));
    }
    std::set<std::string> names(m.meshes);
    for (const VertexSelection& s : m.vertices)
        names.insert(s.mesh);
    for (const std::string& name : names)
        if (std::none_of(c.meshes.begin(), c.meshes.end(), [&](const CharacterMesh& t) { return t.mesh->name == name; })) {
            std::cerr << m.guide << ": error: no mesh named '" << name << "' in the guide's models\n";
            ok = false;
        }
    return ok ? std::optional(std::move(targets)) : std::nullopt;
}

// The mesh's current weights on the rig's bones, if it has ones that fit it.
std::optional<model::MeshWeights> existingWeights(const Character& c, const CharacterMesh& mesh)
{
    if (mesh.binding < 0 || !model::bindingFits(c.guide.bindings[std::size_t(mesh.binding)], *mesh.mesh))
        return std::nullopt;
    const model::MeshWeights& weights = c.guide.bindings[std::size_t(mesh.binding)].weights;
    if (isOnBones(weights, c.bones))
        return weights;
    auto retargeted = skin::retargetWeights(weights, c.bones, mesh.mesh->name);
    print(retargeted.diagnostics());
    return retargeted ? std::optional(retargeted.take()) : std::nullopt;
}

// The import's weights where it writes, the existing ones elsewhere.
model::MeshWeights scoped(const ImportArguments& m, const Character& c, const std::vector<skin::SkinChunk>& chunks,
                          const skin::MeshImportReport& report, ImportTarget& t, model::MeshWeights imported)
{
    const std::size_t n = t.mesh.mesh->vertexCount();
    const std::vector<bool> write = skin::writtenVertices(chunks, report, n, {t.whole ? nullptr : &t.selection, m.append});
    t.written = std::size_t(std::count(write.begin(), write.end(), true));
    if (t.written == n)
        return imported;
    const auto existing = existingWeights(c, t.mesh);
    auto kept = existing ? skin::keepUnwritten(*existing, imported, write) : std::nullopt;
    if (!kept) {
        std::cerr << t.mesh.model << ": warning: mesh '" << t.mesh.mesh->name << "' has no weights that fit it to keep: all " << n
                  << " vertices get the imported weights\n";
        t.written = n;
        return imported;
    }
    t.kept = n - t.written;
    return std::move(*kept);
}

// The mesh's record in the guide gets the scoped weights.
void bindImported(const ImportArguments& m, Character& c, const std::vector<skin::SkinChunk>& chunks, const skin::MeshImportReport& report,
          ImportTarget& t, model::MeshWeights imported)
{
    model::MeshBinding binding{t.mesh.model, t.mesh.mesh->name, t.mesh.mesh->vertexCount(), model::topologyFingerprint(*t.mesh.mesh),
                               scoped(m, c, chunks, report, t, std::move(imported))};
    if (t.mesh.binding >= 0)
        c.guide.bindings[std::size_t(t.mesh.binding)] = std::move(binding);
    else
        c.guide.bindings.push_back(std::move(binding));
    printImportReport(report, t);
}

// The created joints into the guide, saved (before the weights that name
// them), and the rig rebuilt with them for the chunks kept beside the weights.
bool addCreatedJoints(const ImportArguments& m, Character& c, const session::CreatedInfluences& created)
{
    edit::History history(c.guide);
    const Status added = session::addCreatedInstances(history, created);
    print(added.diagnostics());
    if (added.failed())
        return false;
    model::Rig rig = rigging::buildRig(c.guide, *c.templates);
    if (hasErrors(rig.diagnostics)) {
        print(rig.diagnostics);
        return false;
    }
    const Status saved = io::saveGuideFile(c.guide, m.guide);
    print(saved.diagnostics());
    if (saved.failed())
        return false;
    for (const session::CreatedInfluence& joint : created.influences)
        std::cout << "created joint: " << joint.boneName << " (influence " << joint.influence << ") under " << joint.parent << '\n';
    std::cout << "guide: " << m.guide << '\n';
    c.rig = std::move(rig);
    return true;
}

} // namespace

int runSkinImport(const std::vector<std::string>& args)
{
    ImportArguments m;
    if (const int usage = parseImport(args, m))
        return usage;
    const HumanLinesAside aside(m.json);
    if (!canWriteBeside(io::weightsPathFor(m.guide), "weights"))
        return 1;
    auto chunks = readSources(m);
    auto character = chunks ? loadCharacter(m.guide) : std::nullopt;
    if (!character)
        return 1;
    Character& c = *character;
    std::vector<skin::SkinBone> bones = c.bones;
    std::vector<std::string> names = boneNames(c);
    skin::InfluenceMapOptions rules = m.influences;
    session::CreatedInfluences created;
    if (rules.missing == skin::MissingInfluences::Create) { // the missing ones become joints of the guide
        if (!canWriteBeside(m.guide, "guide"))
            return 1;
        auto planned = session::planCreatedInfluences(c.guide, c.rig, *c.templates, *chunks, m.influences, bones, names);
        print(planned.diagnostics());
        if (!planned)
            return 1;
        created = planned.take();
        rules = session::rulesWithCreated(m.influences, created);
    }
    auto resolved = skin::resolveInfluences(*chunks, bones, names, rules);
    print(resolved.diagnostics());
    auto targets = resolved ? importTargets(m, c) : std::nullopt;
    if (!targets)
        return 1;
    session::markCreated(*resolved, created);
    *chunks = skin::applyInfluences(std::move(*chunks), *resolved, bones, names);
    std::vector<const model::Mesh*> meshes;
    for (const ImportTarget& t : *targets)
        meshes.push_back(t.mesh.mesh);
    m.options.progress = progressPrinter("importing weights", m.progress);
    std::vector<skin::MeshImportReport> reports;
    auto imported = skin::importChunks(*chunks, meshes, m.options, &reports);
    print(imported.diagnostics());
    if (!imported)
        return 1;
    for (std::size_t i = 0; i < targets->size(); ++i)
        bindImported(m, c, *chunks, reports[i], (*targets)[i], std::move((*imported)[i]));
    if (!created.empty() && !addCreatedJoints(m, c, created))
        return 1;
    const Status saved = io::saveGuideWeights(c.guide, m.guide);
    print(saved.diagnostics());
    if (saved.failed())
        return 1;
    std::cout << "weights: " << io::weightsPathFor(m.guide) << '\n';
    // The meshes as bound, to re-fit from later; a damaged file there is left alone.
    auto previous = io::loadGuideChunks(m.guide);
    print(previous.diagnostics());
    if (previous) {
        const Status kept = io::saveGuideChunks(boundMeshChunks(c, *previous), m.guide);
        print(kept.diagnostics());
        if (kept.failed())
            return 1;
    }
    return writeImportJson(m, *chunks, *targets, reports, *resolved);
}

} // namespace rs::cli

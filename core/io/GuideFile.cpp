#include "io/GuideFile.h"

#include "base/TextScalars.h"
#include "io/GuidePose.h"
#include "io/ModFile.h"
#include "io/BuildSettingsFile.h"
#include "io/OverrideFile.h"
#include "io/YamlSupport.h"
#include "templates/Manifest.h"
#include "templates/NodeNames.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <filesystem>
#include <map>
#include <optional>
#include <set>

namespace rs::io {

using model::GuideDocument;
using model::GuideJoint;
using model::TemplateInstance;
namespace fs = std::filesystem;

namespace {


void readJoint(YamlReader& r, const YAML::Node& node, TemplateInstance& instance, bool& ok)
{
    const std::string what = "joint of instance '" + instance.name + "'";
    if (!r.expectMap(node, what)) { ok = false; return; }
    GuideJoint joint;
    for (const auto& kv : node) {
        const std::string key = kv.first.Scalar();
        const YAML::Node& v = kv.second;
        if (key == "id") { if (auto i = r.integer(v, "joint id"); i && *i > 0) joint.id = model::JointId(*i); else { if (i) r.error(v, "joint id must be positive"); ok = false; } }
        else if (key == "parent") { if (auto i = r.integer(v, "joint parent")) joint.parent = model::JointId(*i); else ok = false; }
        else if (key == "name") { if (auto s = r.string(v, "joint name")) joint.name = *s; else ok = false; }
        else if (key == "t") { if (auto x = r.vec3(v, "joint translate 't'")) joint.local.translate = *x; else ok = false; }
        else if (key == "r") { if (auto x = r.vec3(v, "joint rotate 'r'")) joint.local.rotateDegrees = *x; else ok = false; }
        else if (key == "s") { if (auto x = r.vec3(v, "joint scale 's'")) joint.local.scale = *x; else ok = false; }
        else if (key == "tags") {
            if (!r.expectSequence(v, "joint tags")) { ok = false; continue; }
            for (const auto& t : v)
                if (auto s = r.string(t, "joint tag")) joint.tags.push_back(*s); else ok = false;
        } else r.warning(kv.first, "unknown key '" + key + "' in " + what);
    }
    if (joint.id == model::kNoId && ok) { r.error(node, what + " has no 'id'"); ok = false; }
    instance.joints.push_back(std::move(joint));
}

// What a schema-2 guide kept outside `overrides:`, migrated once every instance is read.
struct LegacyRecords {
    std::map<model::InstanceId, std::map<std::string, model::ShapeEdit>> shapes; // instance `shapes:`
    model::PoseValues pose;                                                       // top-level `pose:`
    std::optional<SourceLocation> where;                                         // the first, for the note
};

// Orientation options (core.joints, core.bones, rig.spline): an up_axis on the
// aim_axis's line is refused where it is written. Against a template's default
// only the build can tell (it reports it naming the option).
bool checkAxisPair(YamlReader& r, const YAML::Node& options)
{
    const YAML::Node aim = options["aim_axis"], up = options["up_axis"];
    if (!aim || !up || !aim.IsScalar() || !up.IsScalar())
        return true;
    const auto a = templates::parseAxis(aim.Scalar()), u = templates::parseAxis(up.Scalar());
    if (!a || !u || std::abs(glm::dot(*a, *u)) < 0.5)
        return true;
    r.error(up, "option up_axis '" + up.Scalar() + "' lies along aim_axis '" + aim.Scalar() +
                    "' (equal or opposite): the up axis must be another axis");
    return false;
}

// add_nodes (builders/ControlNodes.h) and add_chains (builders/LimbTwist.h):
// a bad name is refused where it is written.
bool checkNameList(YamlReader& r, const YAML::Node& options, const std::string& option,
                   std::vector<std::string> (*problemsOf)(const std::vector<std::string>&))
{
    const YAML::Node v = options[option];
    auto items = v && v.IsScalar() ? parseFlowList(v.Scalar()) : Result<std::vector<std::string>>(std::vector<std::string>{});
    if (v && v.IsSequence()) { // written unquoted: [inf, pose]
        std::vector<std::string> names;
        for (const auto& e : v)
            names.push_back(e.IsScalar() ? e.Scalar() : std::string());
        items = Result<std::vector<std::string>>(std::move(names));
    }
    const auto problems = items.ok() ? problemsOf(*items) : std::vector<std::string>{"is no list"};
    for (const std::string& problem : problems)
        r.error(v, "option " + option + " " + problem);
    return problems.empty();
}

// digit.finger's target_weights written unquoted ([1, 1, 0.5], as Mikan
// writes it) loads as its quoted text, whatever its length (three numbers
// would otherwise be a vector); its items are checked at build, at its line.
std::optional<Value> readNumberList(YamlReader& r, const YAML::Node& v)
{
    std::string text = "[";
    for (std::size_t i = 0; i < v.size(); ++i) {
        if (!v[i].IsScalar()) {
            r.error(v[i], "option target_weights: each item must be a number");
            return std::nullopt;
        }
        text += (i ? ", " : "") + v[i].Scalar();
    }
    return Value(text + "]");
}

bool readInstance(YamlReader& r, const YAML::Node& node, GuideDocument& doc, std::map<model::InstanceId, YAML::Node>& nodes,
                  LegacyRecords& legacy)
{
    if (!r.expectMap(node, "an instance"))
        return false;
    bool ok = true;
    TemplateInstance instance;
    YAML::Node jointsNode;
    std::map<std::string, model::ShapeEdit> shapes;
    for (const auto& kv : node) {
        const std::string key = kv.first.Scalar();
        const YAML::Node& v = kv.second;
        if (key == "id") { if (auto i = r.integer(v, "instance id"); i && *i > 0) instance.id = model::InstanceId(*i); else { if (i) r.error(v, "instance id must be positive"); ok = false; } }
        else if (key == "template") { if (auto s = r.string(v, "template")) instance.templateId = *s; else ok = false; }
        else if (key == "name") { if (auto s = r.string(v, "name")) instance.name = *s; else ok = false; }
        else if (key == "parent") { if (auto i = r.integer(v, "parent instance id")) instance.parent = model::InstanceId(*i); else ok = false; }
        else if (key == "hook") { if (auto i = r.integer(v, "hook joint id")) instance.parentJoint = model::JointId(*i); else ok = false; }
        else if (key == "options") {
            if (!r.expectMap(v, "options")) { ok = false; continue; }
            for (const auto& o : v)
                if (auto value = o.first.Scalar() == "target_weights" && o.second.IsSequence() ? readNumberList(r, o.second)
                                                                                               : readValue(r, o.second, "option " + o.first.Scalar())) {
                    instance.options[o.first.Scalar()] = *value;
                    instance.optionSources.at[o.first.Scalar()] = locationOf(o.second, r.file());
                } else {
                    ok = false;
                }
            ok = checkAxisPair(r, v) && ok;
            ok = checkNameList(r, v, "add_nodes", templates::addNodesProblems) && ok;
            ok = checkNameList(r, v, "add_chains", templates::addChainsProblems) && ok;
        } else if (key == "structure" || key == "names") {
            if (!r.expectMap(v, key)) { ok = false; continue; }
            auto& target = key == "structure" ? instance.structure : instance.names;
            for (const auto& o : v)
                if (auto text = r.string(o.second, key + " " + o.first.Scalar())) target[o.first.Scalar()] = *text;
                else ok = false;
        } else if (key == "shapes") { // schema 2: now shape overrides
            ok = readLegacyShapes(r, v, shapes) && ok;
            if (!shapes.empty() && !legacy.where) legacy.where = locationOf(kv.first, r.file());
        } else if (key == "joints") jointsNode = v;
        else r.warning(kv.first, "unknown key '" + key + "' in an instance");
    }
    if (instance.id == model::kNoId) { if (ok) r.error(node, "instance has no 'id'"); return false; }
    if (instance.templateId.empty()) { r.error(node, "instance " + std::to_string(instance.id) + " has no 'template'"); ok = false; }
    if (instance.name.empty()) { r.error(node, "instance " + std::to_string(instance.id) + " has no 'name'"); ok = false; }
    if (!jointsNode || !r.expectSequence(jointsNode, "joints") || jointsNode.size() == 0) {
        if (!jointsNode || jointsNode.IsSequence()) r.error(node, "instance '" + instance.name + "' has no joints");
        return false;
    }
    for (const auto& j : jointsNode)
        readJoint(r, j, instance, ok);
    nodes[instance.id] = node;
    if (!shapes.empty())
        legacy.shapes[instance.id] = std::move(shapes);
    doc.insertInstance(std::move(instance), doc.instances().size());
    return ok;
}

// Checks references between instances and joints; collects every problem.
void validate(YamlReader& r, const GuideDocument& doc, std::map<model::InstanceId, YAML::Node>& nodes)
{
    std::set<model::InstanceId> seenInstances;
    std::set<model::JointId> seenJoints;
    std::set<std::string> names;
    for (const TemplateInstance& i : doc.instances()) {
        const YAML::Node node = nodes[i.id];
        if (!seenInstances.insert(i.id).second)
            r.error(node, "duplicate instance id " + std::to_string(i.id));
        if (!names.insert(i.name).second)
            r.error(node, "duplicate instance name '" + i.name + "'");
        if (i.parent != model::kNoId) {
            if (!seenInstances.count(i.parent))
                r.error(node, "instance '" + i.name + "': parent " + std::to_string(i.parent) +
                                  " is not an instance listed before it");
            else if (!doc.instance(i.parent)->joint(i.parentJoint))
                r.error(node, "instance '" + i.name + "': hook " + std::to_string(i.parentJoint) +
                                  " is not a joint of its parent '" + doc.instance(i.parent)->name + "'");
        } else if (i.parentJoint != model::kNoId) {
            r.error(node, "instance '" + i.name + "' has a hook but no parent");
        }
        std::set<model::JointId> local;
        for (std::size_t k = 0; k < i.joints.size(); ++k) {
            const GuideJoint& j = i.joints[k];
            if (!seenJoints.insert(j.id).second)
                r.error(node, "duplicate joint id " + std::to_string(j.id));
            if (k == 0 && j.parent != model::kNoId)
                r.error(node, "instance '" + i.name + "': the first joint is the root and has no parent");
            if (k > 0 && (j.parent == model::kNoId || !local.count(j.parent)))
                r.error(node, "instance '" + i.name + "': joint " + std::to_string(j.id) +
                                  " must name a parent joint listed before it");
            local.insert(j.id);
        }
    }
}

// `naming: suffix`, or a map: {preset: suffix, controller: _ctl, side: _, lowercase: on}.
void readNaming(YamlReader& r, const YAML::Node& node, model::NamingRules& rules)
{
    auto preset = [&](const YAML::Node& n) {
        if (auto name = r.string(n, "naming preset")) {
            if (auto p = model::namingPreset(*name)) rules = *p;
            else r.error(n, "unknown naming preset '" + *name + "' (known: mikan, suffix)");
        }
    };
    if (node.IsScalar()) { preset(node); return; }
    if (!r.expectMap(node, "naming")) return;
    if (node["preset"]) preset(node["preset"]);
    for (const auto& kv : node) {
        const std::string key = kv.first.Scalar();
        std::string* field = key == "offset" ? &rules.offset : key == "controller" ? &rules.controller
                           : key == "skin" ? &rules.skin : key == "group" ? &rules.group : key == "side" ? &rules.side : nullptr;
        if (field) { if (auto s = r.string(kv.second, "naming." + key)) *field = *s; }
        else if (key == "suffixes") { if (auto b = r.boolean(kv.second, "naming.suffixes")) rules.suffixes = *b; }
        else if (key == "lowercase") { if (auto b = r.boolean(kv.second, "naming.lowercase")) rules.lowercase = *b; }
        else if (key != "preset") r.warning(kv.first, "unknown key '" + key + "' in naming");
    }
}

// A schema-2 guide's shape edits and keyed test pose become override records;
// a node with a record of its own in `overrides:` as well is an error (which wins is unclear).
void migrateLegacyRecords(YamlReader& r, LegacyRecords& legacy, GuideDocument& doc)
{
    std::size_t migrated = 0;
    for (auto& [id, shapes] : legacy.shapes)
        for (auto& [tag, edit] : shapes) {
            model::Override& record = doc.overrides[NodeKey{id, {}, tag}];
            if (record.shape) {
                r.diagnostics().push_back(makeError(*legacy.where, "instance " + std::to_string(id) + ": the shape of '" + tag +
                                                                       "' is given both in 'shapes' and in 'overrides'"));
                continue;
            }
            record.shape.emplace().edit = std::move(edit);
            ++migrated;
        }
    for (auto& [key, channels] : legacy.pose) {
        model::Override& record = doc.overrides[key];
        if (!record.pose.empty()) {
            r.diagnostics().push_back(makeError(*legacy.where, "the test pose of node '" + key.tag + "' (instance " +
                                                                   std::to_string(key.instance) + ") is given both in 'pose' and in 'overrides'"));
            continue;
        }
        record.pose = std::move(channels);
        ++migrated;
    }
    if (migrated > 0)
        r.diagnostics().push_back({Severity::Note, *legacy.where,
                                   std::to_string(migrated) + " shape edit and test pose record(s) of an older guide were read as "
                                   "overrides; the guide is written with one 'overrides' section when saved", {}});
}

} // namespace

Result<GuideDocument> readGuideText(const std::string& text, const std::string& displayName)
{
    auto yaml = loadYamlText(text, displayName);
    if (!yaml)
        return Result<GuideDocument>::failure(yaml.takeDiagnostics());
    Diagnostics diagnostics;
    YamlReader r(displayName, diagnostics);
    const YAML::Node root = *yaml;
    if (!root.IsMap() || !root[kGuideFormatKey]) {
        r.error(root, std::string("not a Rigsmith guide: the file must start with '") + kGuideFormatKey + ": <version>'");
        return Result<GuideDocument>::failure(diagnostics);
    }
    auto version = r.integer(root[kGuideFormatKey], "schema version");
    if (version && *version > GuideDocument::kSchemaVersion)
        r.error(root[kGuideFormatKey], "schema version " + std::to_string(*version) + " is newer than this Rigsmith (" +
                                      std::to_string(GuideDocument::kSchemaVersion) + ")");
    GuideDocument doc;
    std::map<model::InstanceId, YAML::Node> nodes;
    std::vector<LegacyPoseRecord> legacyPose;
    LegacyRecords legacy;
    YAML::Node modsNode;
    for (const auto& kv : root) {
        const std::string key = kv.first.Scalar();
        if (key == kGuideFormatKey) continue;
        if (key == "name") { if (auto s = r.string(kv.second, "name")) doc.name = *s; }
        else if (key == "naming") readNaming(r, kv.second, doc.naming);
        else if (key == "pose" || key == "legacy_pose") {
            readPose(r, kv.second, legacy.pose, legacyPose);
            if (!legacy.pose.empty() && !legacy.where) legacy.where = locationOf(kv.first, r.file());
        }
        else if (key == "overrides") readOverrides(r, kv.second, doc.overrides);
        else if (key == "mods") modsNode = kv.second; // read once the instances are: names resolve to ids
        else if (key == "build") readBuildSettings(r, kv.second, doc.build);
        else if (key == "reference_model") { // an older guide's one see-through model: now one of its models
            if (auto s = r.string(kv.second, "reference_model"); s && !s->empty() &&
                std::find(doc.models.begin(), doc.models.end(), *s) == doc.models.end())
                doc.models.insert(doc.models.begin(), *s);
        }
        else if (key == "models") {
            if (kv.second.IsNull()) continue;
            if (!r.expectSequence(kv.second, "models")) continue;
            for (const auto& item : kv.second)
                if (auto s = r.string(item, "models")) {
                    if (s->empty()) r.error(item, "a model path is empty");
                    else if (std::find(doc.models.begin(), doc.models.end(), *s) == doc.models.end()) doc.models.push_back(*s);
                }
        }
        else if (key == "instances") {
            if (kv.second.IsNull()) continue;
            if (!r.expectSequence(kv.second, "instances")) continue;
            for (const auto& node : kv.second)
                readInstance(r, node, doc, nodes, legacy);
        } else r.warning(kv.first, "unknown key '" + key + "' (ignored)");
    }
    if (modsNode)
        readMods(r, modsNode, doc);
    if (!hasErrors(diagnostics))
        validate(r, doc, nodes);
    if (!hasErrors(diagnostics))
        migrateLegacyRecords(r, legacy, doc);
    if (!hasErrors(diagnostics))
        migrateLegacyPose(r, legacyPose, doc);
    if (hasErrors(diagnostics))
        return Result<GuideDocument>::failure(diagnostics);
    return Result<GuideDocument>(std::move(doc), std::move(diagnostics));
}

Result<GuideDocument> readGuideFile(const std::string& path)
{
    auto text = readTextFile(path);
    if (!text)
        return Result<GuideDocument>::failure(text.takeDiagnostics());
    auto doc = readGuideText(*text, path);
    if (doc)
        for (std::string& model : doc->models)
            if (fs::path(model).is_relative())
                model = (fs::absolute(path).parent_path() / model).lexically_normal().string();
    return doc;
}

} // namespace rs::io

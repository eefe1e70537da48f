// The guide's test pose section: read (schema 2 records and schema-1 name
// keys, migrated), written one line per node.
#include "io/GuidePose.h"

#include "model/Value.h"

namespace rs::io {

namespace {

// Channel values of one pose record: {rz: 30, ik_blend: 0}.
void readChannels(YamlReader& r, const YAML::Node& node, const std::string& what, std::map<std::string, double>& out)
{
    if (!r.expectMap(node, what)) return;
    for (const auto& channel : node)
        if (auto value = r.number(channel.second, what + " channel '" + channel.first.Scalar() + "'"))
            out[channel.first.Scalar()] = *value;
}

} // namespace

// pose: the rigger's test pose, one record per node:
//   - {instance: 4, branch: L, node: ctrls.fk.0, values: {rz: 30}}
// (schema 1 wrote a map keyed "arm.L::ctrls.fk.0": read as legacy records).
void readPose(YamlReader& r, const YAML::Node& node, model::PoseValues& pose, std::vector<LegacyPoseRecord>& legacy)
{
    if (node.IsNull()) return;
    if (node.IsMap()) { // schema 1, or a guide's `legacy_pose`
        for (const auto& entry : node) {
            LegacyPoseRecord record{entry.first.Scalar(), {}, locationOf(entry.first, r.file())};
            readChannels(r, entry.second, "pose of '" + record.text + "'", record.channels);
            legacy.push_back(std::move(record));
        }
        return;
    }
    if (!r.expectSequence(node, "pose")) return;
    for (const auto& entry : node) {
        if (!r.expectMap(entry, "a pose record")) continue;
        NodeKey key;
        std::map<std::string, double> channels;
        bool hasInstance = false, hasNode = false;
        for (const auto& kv : entry) {
            const std::string field = kv.first.Scalar();
            if (field == "instance") {
                auto id = r.integer(kv.second, "pose record 'instance'");
                if (id && (*id <= 0 || *id > 0xffffffffLL)) r.error(kv.second, "pose record 'instance' must be an instance id (1 or more)");
                else if (id) { key.instance = model::InstanceId(*id); hasInstance = true; }
            } else if (field == "branch") {
                if (auto b = r.string(kv.second, "pose record 'branch'")) key.branch = *b;
            } else if (field == "node") {
                if (auto t = r.string(kv.second, "pose record 'node'")) { key.tag = *t; hasNode = !t->empty(); }
            } else if (field == "values") {
                readChannels(r, kv.second, "pose record", channels);
            } else {
                r.warning(kv.first, "unknown key '" + field + "' in a pose record (ignored)");
            }
        }
        if (!hasInstance || !hasNode) {
            r.error(entry, "a pose record needs 'instance' (an id) and 'node' (a tag such as ctrls.fk.0)");
            continue;
        }
        if (pose.count(key)) {
            r.error(entry, "a second pose record for the same node");
            continue;
        }
        pose[key] = std::move(channels);
    }
}

// The one place the schema-1 text form of a node is parsed: "<name>[.<branch>]::<tag>".
// Records whose instance name matches an instance become keyed records; the
// others are kept as they are (written back under `legacy_pose`) and reported.
void migrateLegacyPose(YamlReader& r, std::vector<LegacyPoseRecord>& legacy, model::GuideDocument& doc)
{
    std::size_t migrated = 0;
    SourceLocation first;
    for (LegacyPoseRecord& record : legacy) {
        const auto separator = record.text.find("::");
        const std::string copy = record.text.substr(0, separator);
        const std::string name = copy.substr(0, copy.find('.'));
        const model::TemplateInstance* instance = separator == std::string::npos ? nullptr : doc.instanceNamed(name);
        if (!instance) {
            r.diagnostics().push_back(makeWarning(record.where, "pose of '" + record.text + "': no instance named '" + name +
                                                                    "'; the record is kept in the guide (legacy_pose)"));
            doc.legacyPose[record.text] = std::move(record.channels);
            continue;
        }
        NodeKey key{instance->id, copy.size() > name.size() ? copy.substr(name.size() + 1) : std::string(),
                    record.text.substr(separator + 2)};
        if (migrated++ == 0) first = record.where;
        auto& channels = doc.overrides[key].pose;
        for (auto& [channel, value] : record.channels)
            channels[channel] = value;
    }
    if (migrated > 0)
        r.diagnostics().push_back({Severity::Note, first,
                                   std::to_string(migrated) + " pose record(s) keyed by instance name were migrated to instance "
                                   "ids (renaming an instance keeps them); the guide is written in the new form when saved", {}});
}

void writeLegacyPose(std::ostream& out, const model::GuideDocument& doc)
{
    auto writeChannels = [&out](const std::map<std::string, double>& channels) {
        out << "{";
        bool first = true;
        for (const auto& [channel, value] : channels) {
            out << (first ? "" : ", ") << quoteIfNeeded(channel) << ": " << formatNumber(value);
            first = false;
        }
        out << "}";
    };
    if (!doc.legacyPose.empty()) { // an older guide's records that named no instance: kept
        out << "legacy_pose:\n";
        for (const auto& [text, channels] : doc.legacyPose) {
            out << "  " << quoteIfNeeded(text) << ": ";
            writeChannels(channels);
            out << "\n";
        }
    }
}

} // namespace rs::io

// The guide's overrides section: read with an error at the line of every bad
// record, written sorted (the map's key order) one record per node.
#include "io/OverrideFile.h"

#include "model/Value.h"

#include <cmath>

namespace rs::io {

namespace {

std::string vec3Text(const Vec3& v)
{
    return formatValue(Value(v));
}

// One moved CV of a shape edit: {curve: 0, cv: 3, offset: [x, y, z]}.
bool readCvOffset(YamlReader& r, const YAML::Node& node, const std::string& what, model::ShapeEdit& edit)
{
    if (!r.expectMap(node, what + " CV"))
        return false;
    std::int64_t curve = -1, cv = -1; // -1: missing or not an integer
    std::optional<Vec3> offset;
    for (const auto& kv : node) {
        const std::string key = kv.first.Scalar();
        if (key == "curve") curve = r.integer(kv.second, what + " CV 'curve'").value_or(-1);
        else if (key == "cv") cv = r.integer(kv.second, what + " CV 'cv'").value_or(-1);
        else if (key == "offset") offset = r.vec3(kv.second, what + " CV 'offset'");
        else r.warning(kv.first, "unknown key '" + key + "' in a CV of the " + what);
    }
    if (!offset || curve < 0 || cv < 0 || curve > 1'000'000 || cv > 1'000'000) {
        r.error(node, what + ": a CV needs curve and cv (indices from 0) and an offset [x, y, z]");
        return false;
    }
    if (!edit.cvs.emplace(std::pair{int(curve), int(cv)}, *offset).second) {
        r.error(node, what + ": CV " + std::to_string(cv) + " of curve " + std::to_string(curve) + " is given twice");
        return false;
    }
    return true;
}

bool readCvs(YamlReader& r, const YAML::Node& node, const std::string& what, model::ShapeEdit& edit)
{
    if (!r.expectSequence(node, what + " 'cvs'"))
        return false;
    bool ok = true;
    for (const auto& cv : node)
        ok = readCvOffset(r, cv, what, edit) && ok;
    return ok;
}

// {t: [...], r: [...], s: [...]} into `t`; other keys go to `extra` (false: not taken).
template <class Extra>
bool readTransformMap(YamlReader& r, const YAML::Node& node, const std::string& what, Transform& t, Extra extra)
{
    if (!r.expectMap(node, what))
        return false;
    bool ok = true;
    for (const auto& kv : node) {
        const std::string key = kv.first.Scalar();
        Vec3* target = key == "t" ? &t.translate : key == "r" ? &t.rotateDegrees : key == "s" ? &t.scale : nullptr;
        if (target) {
            if (auto x = r.vec3(kv.second, what + " '" + key + "'")) *target = *x;
            else ok = false;
        } else if (!extra(key, kv.second)) {
            r.warning(kv.first, "unknown key '" + key + "' in the " + what);
        }
    }
    return ok;
}

bool readShape(YamlReader& r, const YAML::Node& node, model::ShapeOverride& shape)
{
    bool ok = true;
    ok = readTransformMap(r, node, "shape override", shape.edit.transform, [&](const std::string& key, const YAML::Node& v) {
        if (key == "color") {
            auto c = r.vec3(v, "shape 'color'");
            if (c && (c->x < 0 || c->y < 0 || c->z < 0 || c->x > 1 || c->y > 1 || c->z > 1)) {
                r.error(v, "shape 'color' needs three numbers from 0 to 1 (sRGB)");
                ok = false;
            } else if (c) shape.color = *c;
            else ok = false;
        } else if (key == "line_width") {
            auto w = r.number(v, "shape 'line_width'");
            if (w && *w > 0) shape.lineWidth = *w;
            else { if (w) r.error(v, "shape 'line_width' must be more than 0 (pixels)"); ok = false; }
        } else if (key == "visible") {
            if (auto b = r.boolean(v, "shape 'visible'")) shape.visible = *b;
            else ok = false;
        } else return false;
        return true;
    }) && ok;
    return ok;
}

bool readChannelNumbers(YamlReader& r, const YAML::Node& node, const std::string& what, std::map<std::string, double>& out)
{
    if (!r.expectMap(node, what)) return false;
    bool ok = true;
    for (const auto& channel : node)
        if (auto value = r.number(channel.second, what + " channel '" + channel.first.Scalar() + "'"))
            out[channel.first.Scalar()] = *value;
        else ok = false;
    return ok;
}

bool readLimits(YamlReader& r, const YAML::Node& node, std::map<std::string, model::ChannelLimit>& out)
{
    if (!r.expectMap(node, "limits")) return false;
    bool ok = true;
    for (const auto& channel : node) {
        const std::string what = "limits of '" + channel.first.Scalar() + "'";
        const YAML::Node& v = channel.second;
        if (!v.IsSequence() || v.size() != 2) { r.error(v, what + " must be [min, max]"); ok = false; continue; }
        auto low = r.number(v[0], what + " min"), high = r.number(v[1], what + " max");
        if (!low || !high) { ok = false; continue; }
        if (*low > *high) { r.error(v, what + ": min " + formatNumber(*low) + " is above max " + formatNumber(*high)); ok = false; continue; }
        out[channel.first.Scalar()] = {*low, *high};
    }
    return ok;
}

bool readLocks(YamlReader& r, const YAML::Node& node, std::map<std::string, model::ChannelState>& out)
{
    if (!r.expectMap(node, "locks")) return false;
    bool ok = true;
    for (const auto& channel : node) {
        const std::string what = "locks of '" + channel.first.Scalar() + "'";
        if (!r.expectMap(channel.second, what)) { ok = false; continue; }
        model::ChannelState state;
        for (const auto& kv : channel.second) {
            const std::string key = kv.first.Scalar();
            bool* field = key == "locked" ? &state.locked : key == "keyable" ? &state.keyable : nullptr;
            if (!field) { r.warning(kv.first, "unknown key '" + key + "' in the " + what + " (locked, keyable)"); continue; }
            if (auto b = r.boolean(kv.second, what + " '" + key + "'")) *field = *b;
            else ok = false;
        }
        out[channel.first.Scalar()] = state;
    }
    return ok;
}

// One record; false (with an error) when it cannot be kept whole.
bool readRecord(YamlReader& r, const YAML::Node& entry, NodeKey& key, model::Override& record)
{
    if (!r.expectMap(entry, "an override record")) return false;
    bool ok = true, hasInstance = false, hasNode = false;
    for (const auto& kv : entry) {
        const std::string field = kv.first.Scalar();
        const YAML::Node& v = kv.second;
        if (field == "instance") {
            auto id = r.integer(v, "override 'instance'");
            if (id && (*id <= 0 || *id > 0xffffffffLL)) { r.error(v, "override 'instance' must be an instance id (1 or more)"); ok = false; }
            else if (id) { key.instance = model::InstanceId(*id); hasInstance = true; }
            else ok = false;
        } else if (field == "branch") {
            if (auto b = r.string(v, "override 'branch'")) key.branch = *b; else ok = false;
        } else if (field == "node") {
            if (auto t = r.string(v, "override 'node'")) { key.tag = *t; hasNode = !t->empty(); } else ok = false;
        } else if (field == "shape") {
            ok = readShape(r, v, record.shape.emplace()) && ok;
        } else if (field == "cvs") {
            ok = readCvs(r, v, "shape override", record.shape ? record.shape->edit : record.shape.emplace().edit) && ok;
        } else if (field == "defaults") ok = readChannelNumbers(r, v, "defaults", record.defaults) && ok;
        else if (field == "limits") ok = readLimits(r, v, record.limits) && ok;
        else if (field == "locks") ok = readLocks(r, v, record.locks) && ok;
        else if (field == "pose") ok = readChannelNumbers(r, v, "pose", record.pose) && ok;
        else if (field == "post") ok = readTransformMap(r, v, "post transform", record.post.emplace(), [](auto&, auto&) { return false; }) && ok;
        else if (field == "name") {
            auto s = r.string(v, "override 'name'");
            if (s && !s->empty()) record.displayName = *s;
            else { if (s) r.error(v, "override 'name' is empty"); ok = false; }
        } else r.warning(kv.first, "unknown key '" + field + "' in an override record (ignored)");
    }
    if (!hasNode || (!hasInstance && key.tag != "rig")) {
        r.error(entry, "an override record needs 'instance' (an id) and 'node' (a tag such as ctrls.fk.0; 'rig' alone for the rig root)");
        return false;
    }
    if (record.post && !(key == model::rigRootKey())) {
        r.error(entry, "a post transform belongs to the rig root ('node: rig' without an instance)");
        return false;
    }
    return ok;
}

void writeChannels(std::ostream& out, const char* name, const std::map<std::string, double>& channels)
{
    if (channels.empty()) return;
    out << "    " << name << ": {";
    bool first = true;
    for (const auto& [channel, value] : channels) {
        out << (first ? "" : ", ") << quoteIfNeeded(channel) << ": " << formatNumber(value);
        first = false;
    }
    out << "}\n";
}

void writeTransformFields(std::ostream& out, const Transform& t, bool& first)
{
    auto field = [&](const char* key, const Vec3& v) { out << (first ? "" : ", ") << key << ": " << vec3Text(v); first = false; };
    if (t.translate != Vec3(0.0)) field("t", t.translate);
    if (t.rotateDegrees != Vec3(0.0)) field("r", t.rotateDegrees);
    if (t.scale != Vec3(1.0)) field("s", t.scale);
}

void writeRecord(std::ostream& out, const model::GuideDocument& doc, const NodeKey& key, const model::Override& o)
{
    if (key.instance != model::kNoId) {
        out << "  - instance: " << key.instance;
        if (const auto* instance = doc.instance(key.instance)) out << "  # " << instance->name;
        out << "\n";
        if (!key.branch.empty()) out << "    branch: " << quoteIfNeeded(key.branch) << "\n";
        out << "    node: " << quoteIfNeeded(key.tag) << "\n";
    } else {
        out << "  - node: " << quoteIfNeeded(key.tag) << "\n";
    }
    if (o.shape) {
        bool first = true;
        out << "    shape: {";
        writeTransformFields(out, o.shape->edit.transform, first);
        if (o.shape->color) { out << (first ? "" : ", ") << "color: " << vec3Text(*o.shape->color); first = false; }
        if (o.shape->lineWidth) { out << (first ? "" : ", ") << "line_width: " << formatNumber(*o.shape->lineWidth); first = false; }
        if (o.shape->visible) out << (first ? "" : ", ") << "visible: " << (*o.shape->visible ? "on" : "off");
        out << "}\n";
        if (!o.shape->edit.cvs.empty()) {
            out << "    cvs:\n";
            for (const auto& [at, offset] : o.shape->edit.cvs)
                out << "      - {curve: " << at.first << ", cv: " << at.second << ", offset: " << vec3Text(offset) << "}\n";
        }
    }
    writeChannels(out, "defaults", o.defaults);
    if (!o.limits.empty()) {
        out << "    limits: {";
        bool first = true;
        for (const auto& [channel, limit] : o.limits) {
            out << (first ? "" : ", ") << quoteIfNeeded(channel) << ": [" << formatNumber(limit.min) << ", " << formatNumber(limit.max) << "]";
            first = false;
        }
        out << "}\n";
    }
    if (!o.locks.empty()) {
        out << "    locks: {";
        bool first = true;
        for (const auto& [channel, state] : o.locks) {
            out << (first ? "" : ", ") << quoteIfNeeded(channel) << ": {locked: " << (state.locked ? "on" : "off")
                << ", keyable: " << (state.keyable ? "on" : "off") << "}";
            first = false;
        }
        out << "}\n";
    }
    if (o.post) {
        bool first = true;
        out << "    post: {";
        writeTransformFields(out, *o.post, first);
        out << "}\n";
    }
    if (o.displayName) out << "    name: " << quoteIfNeeded(*o.displayName) << "\n";
    writeChannels(out, "pose", o.pose);
}

} // namespace

void readOverrides(YamlReader& r, const YAML::Node& node, model::Overrides& overrides)
{
    if (node.IsNull() || !r.expectSequence(node, "overrides")) return;
    for (const auto& entry : node) {
        NodeKey key;
        model::Override record;
        if (!readRecord(r, entry, key, record)) continue;
        if (overrides.count(key)) { r.error(entry, "a second override record for the same node"); continue; }
        overrides.emplace(std::move(key), std::move(record));
    }
}

bool readLegacyShapes(YamlReader& r, const YAML::Node& node, std::map<std::string, model::ShapeEdit>& shapes)
{
    if (!r.expectMap(node, "shapes")) return false;
    bool ok = true;
    for (const auto& entry : node) {
        const std::string tag = entry.first.Scalar();
        model::ShapeEdit edit;
        const bool read = readTransformMap(r, entry.second, "shape edit of '" + tag + "'", edit.transform,
                                           [&](const std::string& key, const YAML::Node& v) {
                                               if (key != "cvs") return false;
                                               ok = readCvs(r, v, "shape edit of '" + tag + "'", edit) && ok;
                                               return true;
                                           });
        ok = read && ok;
        shapes[tag] = std::move(edit);
    }
    return ok;
}

void writeOverrides(std::ostream& out, const model::GuideDocument& doc)
{
    if (doc.overrides.empty()) return;
    out << "overrides:\n";
    for (const auto& [key, record] : doc.overrides)
        if (!record.isEmpty())
            writeRecord(out, doc, key, record);
}

} // namespace rs::io

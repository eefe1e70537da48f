#include "rigging/BuildContext.h"

#include "rigging/Fragment.h"
#include "rigging/RigAssembly.h"
#include "base/TextScalars.h"
#include "templates/Structure.h"

#include <algorithm>
#include <cctype>

namespace rs::rigging {

BuildContext::BuildContext(RigAssembly& assembly, const templates::TemplateManifest& manifest,
                           const model::TemplateInstance& instance, std::map<std::string, Value> options)
    : m_assembly(assembly), m_manifest(manifest), m_instance(instance), m_options(std::move(options))
{
}

const model::GuideDocument& BuildContext::guide() const
{
    if (m_record) // it may read anything: generated every time
        m_record->replayable = false;
    return m_assembly.guide;
}

void BuildContext::touch(model::RigNodeIndex index)
{
    if (m_record && index < m_firstNode)
        m_record->replayable = false;
}

const Value& BuildContext::option(const std::string& name) const
{
    static const Value kMissing = false;
    auto it = m_options.find(name);
    if (it == m_options.end()) {
        error("builder asked for option '" + name + "' that the manifest does not declare", name);
        return kMissing;
    }
    return it->second;
}

bool BuildContext::optionBool(const std::string& name) const
{
    const Value& v = option(name);
    return std::holds_alternative<bool>(v) && std::get<bool>(v);
}

long long BuildContext::optionInt(const std::string& name) const
{
    const Value& v = option(name);
    if (auto* i = std::get_if<long long>(&v)) return *i;
    if (auto* d = std::get_if<double>(&v)) return static_cast<long long>(*d);
    return 0;
}

double BuildContext::optionFloat(const std::string& name) const
{
    const Value& v = option(name);
    if (auto* d = std::get_if<double>(&v)) return *d;
    if (auto* i = std::get_if<long long>(&v)) return static_cast<double>(*i);
    return 0.0;
}

std::string BuildContext::optionString(const std::string& name) const
{
    return formatValue(option(name));
}

std::optional<std::vector<std::string>> BuildContext::optionList(const std::string& name) const
{
    const std::string text = optionString(name);
    auto items = parseFlowList(text);
    if (!items) {
        this->error("option '" + name + "' = '" + text + "' is not a YAML list: " + firstError(items.diagnostics()), name);
        return std::nullopt;
    }
    return items.take();
}

std::optional<std::vector<model::JointId>> BuildContext::structure(const std::string& tag) const
{
    const auto& resolved = m_assembly.structureTag(m_manifest, m_instance, tag);
    auto joints = resolved.joints;
    if (!joints)
        error("structure '" + tag + "': " + resolved.error);
    else if (joints->empty())
        error("structure '" + tag + "' resolves to no guide joint");
    if (joints && joints->empty())
        return std::nullopt;
    return joints;
}

Mat4 BuildContext::guideWorldMatrix(model::JointId joint) const
{
    const Mat4 world = m_assembly.guideWorldMatrix(m_assembly.authoredJoint(joint));
    if (m_record)
        m_record->guideReads.emplace_back(joint, world);
    return world;
}

std::vector<model::JointId> BuildContext::taggedJoints(const std::string& tag) const
{
    std::vector<model::JointId> out;
    for (const auto& joint : m_instance.joints)
        if (std::find(joint.tags.begin(), joint.tags.end(), tag) != joint.tags.end())
            out.push_back(joint.id);
    return out;
}

bool BuildContext::mirrored() const { return m_assembly.copyOf(m_instance.id).mirror != Mat4(1.0); }

const Mat4& BuildContext::mirrorMatrix() const { return m_assembly.copyOf(m_instance.id).mirror; }

void BuildContext::setScaleCompensate(model::RigNodeIndex index, bool on)
{
    touch(index);
    m_assembly.rig.nodes.at(index).scaleCompensate = on;
}

const model::RigNode& BuildContext::node(model::RigNodeIndex index) const
{
    const model::RigNode& node = m_assembly.rig.nodes.at(index);
    if (m_record && index < m_firstNode)
        m_record->nodeReads.push_back({node, node.parent == model::kNoNode ? NodeKey{} : m_assembly.rig.nodes[node.parent].key});
    return node;
}

Mat4 BuildContext::nodeWorld(model::RigNodeIndex index) const
{
    const Mat4& m = m_assembly.copyOf(m_instance.id).mirror;
    return m * node(index).worldMatrix * m;
}

std::optional<model::RigNodeIndex> BuildContext::findNode(const std::string& tag) const
{
    return m_assembly.rig.find(m_assembly.keyOf(m_instance, tag));
}

void BuildContext::setHidden(model::RigNodeIndex index)
{
    touch(index);
    m_assembly.rig.nodes.at(index).hidden = true;
}

model::AttributeRef BuildContext::addAttribute(model::RigNodeIndex index, const std::string& name, double value, double min,
                                              double max)
{
    touch(index);
    auto& node = m_assembly.rig.nodes.at(index);
    node.attributes.push_back({name, std::clamp(value, min, max), min, max, {}});
    return {index, name};
}

model::AttributeRef BuildContext::addEnumAttribute(model::RigNodeIndex index, const std::string& name, int value,
                                                  std::vector<std::string> labels)
{
    const double last = labels.empty() ? 0.0 : double(labels.size() - 1);
    model::AttributeRef attribute = addAttribute(index, name, value, 0.0, last);
    m_assembly.rig.nodes.at(index).attributes.back().labels = std::move(labels);
    return attribute;
}

model::ChannelSettings& BuildContext::channels(model::RigNodeIndex index)
{
    touch(index);
    return m_assembly.rig.nodes.at(index).channels;
}

void BuildContext::addConstraint(const std::string& tag, std::vector<model::RigNodeIndex> driven,
                                 std::vector<model::RigNodeIndex> targets, model::ConstraintSettings settings)
{
    model::RigConstraint c;
    c.key = m_assembly.keyOf(m_instance, tag);
    c.path = m_assembly.pathOf(m_instance, tag);
    c.owner = m_assembly.copyOf(m_instance.id).original;
    c.driven = std::move(driven);
    c.targets = std::move(targets);
    c.settings = std::move(settings);
    // Builders work in authored space. On a mirrored copy a rotation about a
    // local axis comes out reversed (M Rk(a) M = Rk(-a) unless k is the mirror
    // axis), so the drive's factor turns with it and the sides stay mirror images.
    if (auto* drive = std::get_if<model::DriveConstraint>(&c.settings); drive && drive->output != model::DriveOutput::Scale) {
        const Mat4& mirror = m_assembly.copyOf(m_instance.id).mirror;
        const int axis = static_cast<int>(drive->output);
        drive->factor *= mirror[(axis + 1) % 3][(axis + 1) % 3] * mirror[(axis + 2) % 3][(axis + 2) % 3];
    }
    for (auto index : c.driven)
        if (index == model::kNoNode) {
            error("constraint '" + c.path + "' has no driven node");
            return;
        }
    for (auto index : c.targets)
        if (index == model::kNoNode) {
            error("constraint '" + c.path + "' has a missing target");
            return;
        }
    m_assembly.rig.constraints.push_back(std::move(c));
}

void BuildContext::defineSpace(const std::string& name, model::RigNodeIndex index) { m_assembly.spaces[name] = index; }

model::RigNodeIndex BuildContext::space(const std::string& name) const
{
    auto it = m_assembly.spaces.find(name);
    const model::RigNodeIndex node = it == m_assembly.spaces.end() ? model::kNoNode : it->second;
    if (m_record)
        m_record->spaceReads.emplace_back(name, node == model::kNoNode ? std::nullopt
                                                                       : std::optional<NodeKey>(m_assembly.rig.nodes.at(node).key));
    return node;
}

std::string BuildContext::nodeName(model::NameRole role, const std::string& token, std::optional<int> index) const
{
    const std::string suffix = m_assembly.copyOf(m_instance.id).suffix;
    std::string core = name(token, index);
    core.resize(core.size() - suffix.size());
    return m_assembly.guide.naming.make(role, core, suffix.empty() ? suffix : suffix.substr(1));
}

std::string BuildContext::markedName(const std::string& mark, const std::string& token, std::optional<int> index) const
{
    model::NamingRules rules = m_assembly.guide.naming;
    rules.group = rules.suffixes ? "_" + mark : mark + "_";
    const std::string suffix = m_assembly.copyOf(m_instance.id).suffix;
    std::string core = name(token, index);
    core.resize(core.size() - suffix.size());
    return rules.make(model::NameRole::Group, core, suffix.empty() ? suffix : suffix.substr(1));
}

std::string BuildContext::name(const std::string& token, std::optional<int> index) const
{
    const BranchCopy& copy = m_assembly.copyOf(m_instance.id);
    std::string out = copy.baseName;
    std::string core;
    if (auto it = m_instance.names.find(token); !token.empty() && it != m_instance.names.end())
        core = it->second; // per-instance override
    else if (!token.empty())
        core = m_manifest.defaultName(token);
    if (!core.empty() && core != out)
        out += "_" + core;
    if (index) {
        if (std::isdigit(static_cast<unsigned char>(out.back())))
            out += "_";
        out += std::to_string(*index);
    }
    return out + copy.suffix;
}

model::RigNodeIndex BuildContext::createNode(model::RigNodeKind kind, const std::string& tag, const std::string& name,
                                             model::RigNodeIndex parent, const Mat4& worldMatrix, model::JointId source)
{
    const Mat4& mirror = m_assembly.copyOf(m_instance.id).mirror;
    model::RigNode node;
    node.key = m_assembly.keyOf(m_instance, tag);
    node.path = m_assembly.pathOf(m_instance, tag);
    node.name = name;
    // A name override keyed by the node's tag (`names: {skin.0: sk_ear}`: a
    // tag has a '.', a naming token has none) names the node exactly, with
    // the branch's side in a branch copy (sk_ear_L); `name` is then unused.
    if (auto it = m_instance.names.find(tag); tag.find('.') != std::string::npos && it != m_instance.names.end()) {
        const std::string& suffix = m_assembly.copyOf(m_instance.id).suffix; // "_L", "_A_L"
        node.name = suffix.empty() ? it->second : it->second + m_assembly.guide.naming.side + suffix.substr(1);
    }
    node.kind = kind;
    node.parent = parent == model::kNoNode ? m_hookNode : parent;
    node.owner = m_assembly.copyOf(m_instance.id).original;
    node.worldMatrix = mirror * worldMatrix * mirror;
    node.guide = source == model::kNoId ? model::kNoId : m_assembly.authoredJoint(source);
    if (kind == model::RigNodeKind::Controller)
        node.channels = model::ChannelSettings::controllerDefaults();
    if (const auto existing = m_assembly.rig.find(node.key)) {
        error("rig node '" + node.path + "' is created twice");
        return *existing;
    }
    return m_assembly.addNode(std::move(node));
}

void BuildContext::setHook(model::JointId joint, model::RigNodeIndex node)
{
    const auto owner = m_assembly.guideIndex.find(joint);
    if (owner == m_assembly.guideIndex.end() || owner->second.owner != &m_instance) {
        error("hook for joint " + std::to_string(joint) + " which is not a joint of this instance");
        return;
    }
    m_assembly.hooks[joint] = node;
}

void BuildContext::report(Severity severity, const std::string& message, const std::string& option) const
{
    std::string text = message;
    if (!option.empty())
        text += " (option '" + option + "')";
    m_assembly.report(severity, &m_instance, text);
    // An option the guide file set: the message points at where it is written.
    if (const auto at = m_instance.optionSources.at.find(option); !option.empty() && at != m_instance.optionSources.at.end())
        m_assembly.rig.diagnostics.back().where = at->second;
    if (severity == Severity::Error)
        m_failed = true;
}

void BuildContext::error(const std::string& message, const std::string& option) const { report(Severity::Error, message, option); }
void BuildContext::warning(const std::string& message, const std::string& option) const { report(Severity::Warning, message, option); }

} // namespace rs::rigging

// Finalize stage: gives every controller its curves from the manifest `shapes`
// entry. A shape is sampled from the library, its Y axis turned per `axis` (an
// axis or an option naming one, if `do_axis` allows),
// scaled so its largest extent is `size` times the instance's control scale
// (ControlSize.cpp: relative to the character), then placed in the guide: under the
// `parent` joint, moved to the average of the `point` joints, and aimed at `aim`
// (a joint or a world axis) with `aim_axis`/`up_axis`/`up`, if `do_aim` allows.
// The curves are stored in the controller's space. `clone` copies another
// controller's curves afterwards; `reference` sends a shape to another id.
// Wildcards (`ctrls.*`) match per index and every `*` in the entry's addresses
// becomes that index.
#include "rigging/RigAssembly.h"
#include "templates/Structure.h"

#include <fnmatch.h>

#include <algorithm>

namespace rs::rigging {

namespace {

using templates::ShapeSpec;

const std::string& tagOf(const model::RigNode& node) { return node.key.tag; }

// `pattern` matched against `tag`; the text the first '*' stood for goes to `capture`.
bool matchKey(const std::string& pattern, const std::string& tag, std::string& capture)
{
    const auto star = pattern.find('*');
    if (star == std::string::npos)
        return pattern == tag;
    if (fnmatch(pattern.c_str(), tag.c_str(), 0) != 0)
        return false;
    const std::string suffix = pattern.substr(pattern.find_last_of('*') + 1);
    capture = pattern.find('*', star + 1) == std::string::npos
        ? tag.substr(star, tag.size() - star - suffix.size()) : std::string();
    return true;
}

std::string substitute(std::string text, const std::string& index)
{
    if (index.empty())
        return text;
    for (auto at = text.find('*'); at != std::string::npos; at = text.find('*', at + index.size()))
        text.replace(at, 1, index);
    return text;
}

struct Match {
    const ShapeSpec* spec = nullptr;
    std::string index; // what '*' stood for
};

// The entry giving `tag` its curves: a `reference` to it, else its own key (exact before wildcard).
Match findSpec(const templates::TemplateManifest& manifest, const std::string& tag)
{
    Match wildcard;
    for (const ShapeSpec& spec : manifest.shapes) {
        std::string index;
        if (!spec.reference.empty()) {
            if (matchKey(spec.reference, tag, index)) return {&spec, index};
            continue;
        }
        if (spec.key == tag) return {&spec, {}};
        if (!wildcard.spec && matchKey(spec.key, tag, index)) wildcard = {&spec, index};
    }
    return wildcard;
}

// A library shape sampled as polylines, with their largest extent.
SampledShape sample(const templates::Shape& shape)
{
    SampledShape out;
    Vec3 lo(1e300), hi(-1e300);
    for (const auto& curve : shape.curves) {
        out.curves.push_back(templates::evaluateCurve(curve));
        for (const Vec3& p : out.curves.back()) {
            lo = glm::min(lo, p);
            hi = glm::max(hi, p);
        }
    }
    const Vec3 extent = hi - lo;
    out.extent = std::max({extent.x, extent.y, extent.z});
    return out;
}

const templates::Shape& fallbackShape()
{
    static const templates::Shape circle = [] {
        templates::Shape s;
        s.name = "circle";
        templates::ShapeCurve c;
        c.degree = 3;
        c.periodic = true;
        const double k = 0.7071067811865476;
        c.points = {{0.5, 0, 0}, {0.5 * k, 0, 0.5 * k}, {0, 0, 0.5}, {-0.5 * k, 0, 0.5 * k},
                    {-0.5, 0, 0}, {-0.5 * k, 0, -0.5 * k}, {0, 0, -0.5}, {0.5 * k, 0, -0.5 * k}};
        s.curves.push_back(c);
        return s;
    }();
    return circle;
}

Mat3 columns(const Vec3& a, const Vec3& b, const Vec3& c) { return Mat3(a, b, c); }

// Rotation taking `from` onto `to` (unit vectors), the shortest way.
Mat3 rotationBetween(const Vec3& from, const Vec3& to)
{
    const double d = glm::dot(from, to);
    if (d < -1.0 + 1e-12) { // opposite: half turn about any perpendicular axis
        Vec3 axis = glm::cross(from, Vec3(1, 0, 0));
        if (glm::length(axis) < 1e-6) axis = glm::cross(from, Vec3(0, 1, 0));
        return glm::mat3_cast(glm::angleAxis(glm::pi<double>(), glm::normalize(axis)));
    }
    return glm::mat3_cast(Quat(from, to));
}

// Places one shape: returns its frame in world space.
class Placer {
public:
    Placer(RigAssembly& a, const InstanceRecord& r) : m_a(a), m_r(r) {}

    std::optional<std::vector<Vec3>> positions(const std::string& address, const std::string& what)
    {
        const auto& resolved = m_a.structureAddress(*m_r.manifest, *m_r.instance, address);
        const auto& joints = resolved.joints;
        const std::string& error = resolved.error;
        if (!joints || joints->empty()) {
            warn(what + ": " + (joints ? "'" + address + "' resolves to no guide joint" : error));
            return std::nullopt;
        }
        std::vector<Vec3> out;
        for (model::JointId j : *joints)
            out.push_back(translationOf(m_a.guideWorldMatrix(j)));
        return out;
    }

    bool aimAllowed(const ShapeSpec& spec) const { return optionsMatch(spec.doAim); }

    // The axis the library's Y axis turns onto: `axis`, or the value of the
    // option it names, when `do_axis` allows; nullopt: the shape stays Y-up.
    std::optional<Vec3> axis(const ShapeSpec& spec) const
    {
        if (spec.axis.empty() || !optionsMatch(spec.doAxis))
            return std::nullopt;
        if (auto axis = templates::parseAxis(spec.axis))
            return axis;
        auto it = m_r.options.find(spec.axis);
        return it == m_r.options.end() ? std::nullopt : templates::parseAxis(formatValue(it->second));
    }

    bool optionsMatch(const std::vector<std::pair<std::string, std::vector<std::string>>>& conditions) const
    {
        for (const auto& [option, accepted] : conditions) {
            auto it = m_r.options.find(option);
            if (it == m_r.options.end())
                return false;
            const std::string value = formatValue(it->second);
            if (std::find(accepted.begin(), accepted.end(), value) == accepted.end())
                return false;
        }
        return true;
    }

    Mat4 frame(const ShapeSpec& spec, const std::string& index, const Mat4& controllerWorld)
    {
        const std::string key = "shapes." + spec.key;
        if (spec.parent.empty() && spec.point.empty() && spec.aim.empty())
            return controllerWorld;
        Mat4 frame = controllerWorld;
        if (!spec.parent.empty()) {
            const auto& resolved = m_a.structureAddress(*m_r.manifest, *m_r.instance, substitute(spec.parent, index));
            const auto& joints = resolved.joints;
            const std::string& error = resolved.error;
            if (joints && !joints->empty()) {
                Vec3 t, s;
                Quat q;
                decompose(m_a.guideWorldMatrix(joints->front()), t, q, s);
                frame = translationMatrix(t) * glm::mat4_cast(q);
            } else {
                warn(key + ".parent: " + (joints ? "resolves to no guide joint" : error));
            }
        }
        if (!spec.point.empty()) {
            Vec3 sum(0.0);
            std::size_t count = 0;
            for (const std::string& address : spec.point)
                if (auto p = positions(substitute(address, index), key + ".point"))
                    for (const Vec3& v : *p) { sum += v; ++count; }
            if (count)
                frame[3] = Vec4(sum / double(count), 1.0);
        }
        if (!spec.aim.empty() && aimAllowed(spec))
            aim(spec, index, frame);
        return frame;
    }

private:
    void aim(const ShapeSpec& spec, const std::string& index, Mat4& frame)
    {
        const std::string key = "shapes." + spec.key;
        const Vec3 origin = Vec3(frame[3]);
        Vec3 direction;
        if (auto axis = templates::parseAxis(spec.aim)) {
            direction = *axis;
        } else if (auto targets = positions(substitute(spec.aim, index), key + ".aim")) {
            Vec3 sum(0.0);
            for (const Vec3& v : *targets) sum += v;
            direction = sum / double(targets->size()) - origin;
        } else {
            return;
        }
        if (glm::length(direction) < 1e-9) {
            warn(key + ".aim: the target is at the shape's position; not aimed");
            return;
        }
        direction = glm::normalize(direction);
        const Vec3 aimAxis = *templates::parseAxis(spec.aimAxis);
        Mat3 rotation = Mat3(frame);
        if (spec.upAxis.empty()) {
            rotation = rotationBetween(glm::normalize(rotation * aimAxis), direction) * rotation;
        } else {
            const Vec3 upAxis = *templates::parseAxis(spec.upAxis);
            if (std::abs(glm::dot(upAxis, aimAxis)) > 1e-6) {
                warn(key + ": aim_axis and up_axis must differ");
                return;
            }
            Vec3 up(0, 1, 0);
            if (auto axis = templates::parseAxis(spec.up)) up = *axis;
            else if (!spec.up.empty()) {
                if (auto targets = positions(substitute(spec.up, index), key + ".up")) up = targets->front() - origin;
                else return;
            }
            up -= direction * glm::dot(up, direction);
            if (glm::length(up) < 1e-9) {
                warn(key + ".up is parallel to the aim; the up axis is free");
                rotation = rotationBetween(glm::normalize(rotation * aimAxis), direction) * rotation;
            } else {
                up = glm::normalize(up);
                const Mat3 local = columns(aimAxis, upAxis, glm::cross(aimAxis, upAxis));
                const Mat3 world = columns(direction, up, glm::cross(direction, up));
                rotation = world * glm::transpose(local);
            }
        }
        frame = translationMatrix(origin) * Mat4(rotation);
    }

    void warn(const std::string& message) { m_a.report(Severity::Warning, m_r.instance, message); }

    RigAssembly& m_a;
    const InstanceRecord& m_r;
};

struct PendingClone {
    model::RigNodeIndex node;
    const InstanceRecord* record;
    const ShapeSpec* spec;
    std::string index;
};

void cloneCurves(RigAssembly& a, const PendingClone& c)
{
    model::RigNode& node = a.rig.nodes[c.node];
    auto found = a.rig.find(a.keyOf(*c.record->instance, substitute(c.spec->clone, c.index)));
    if (!found || a.rig.nodes[*found].curves.empty()) {
        a.report(Severity::Warning, c.record->instance, "shapes." + c.spec->key + ".clone: no controller '" +
                                                            substitute(c.spec->clone, c.index) + "' with curves");
        return;
    }
    const model::RigNode& from = a.rig.nodes[*found];
    // World-space copy, then `size` relative to the source and an optional new colour.
    const Mat4 toLocal = glm::inverse(node.worldMatrix) * from.worldMatrix;
    std::optional<Vec3> color;
    if (!c.spec->color.empty())
        if (auto parsed = templates::parseColor(c.spec->color)) color = Vec3(parsed->r, parsed->g, parsed->b);
    node.shape = from.shape;
    node.curves = from.curves;
    for (auto& curve : node.curves) {
        curve.transform(glm::scale(Mat4(1.0), Vec3(c.spec->size)) * toLocal);
        if (color) curve.color = *color;
    }
}

} // namespace

void applyShapes(RigAssembly& a, ShapeSamples& sampled)
{
    std::map<CopyKey, const InstanceRecord*> records; // by instance copy
    std::vector<PendingClone> clones;
    for (const auto& r : a.records)
        records[a.copyOf(r.instance->id).key()] = &r;
    const bool moved = a.post != Mat4(1.0);
    const Mat4 unpost = moved ? glm::inverse(a.post) : Mat4(1.0);
    for (model::RigNodeIndex n = 0; n < a.rig.nodes.size(); ++n) {
        auto& node = a.rig.nodes[n];
        if (node.kind != model::RigNodeKind::Controller)
            continue;
        auto record = records.find(node.key.copy());
        if (record == records.end())
            continue;
        const InstanceRecord& r = *record->second;
        const Match match = findSpec(*r.manifest, tagOf(node));
        const ShapeSpec* spec = match.spec;
        if (spec && !spec->clone.empty()) {
            clones.push_back({n, &r, spec, match.index});
            continue;
        }
        const templates::Shape* shape = spec ? a.templates.shapes().find(spec->shape) : nullptr;
        if (!shape)
            shape = &fallbackShape();
        templates::Color color{1.0, 1.0, 0.0};
        if (spec && !spec->color.empty()) {
            if (auto parsed = templates::parseColor(spec->color))
                color = *parsed;
            else
                a.report(Severity::Warning, r.instance, "unknown colour '" + spec->color + "' in shapes." + spec->key);
        }
        auto cached = sampled.find(shape);
        if (cached == sampled.end())
            cached = sampled.emplace(shape, sample(*shape)).first;
        const SampledShape& polylines = cached->second;
        const double scale = (spec ? spec->size : 1.0) * a.controlScaleOf(r.instance->id) /
                             (polylines.extent > 0.0 ? polylines.extent : 1.0);
        Mat4 toController(1.0);
        if (spec) {
            Placer placer(a, r);
            // The guide's frame: without the post transform the overrides gave every node.
            const Mat4 world = moved ? unpost * node.worldMatrix : node.worldMatrix;
            toController = glm::inverse(world) * placer.frame(*spec, match.index, world);
            if (const auto axis = placer.axis(*spec))
                toController = toController * Mat4(rotationBetween(Vec3(0, 1, 0), *axis));
        }
        node.shape = shape->name;
        node.curves.clear();
        for (std::size_t k = 0; k < shape->curves.size(); ++k) {
            model::ControllerCurve out;
            out.points.reserve(polylines.curves[k].size());
            for (const Vec3& p : polylines.curves[k])
                out.points.push_back(Vec3(toController * Vec4(p * scale, 1.0)));
            for (const Vec3& p : shape->curves[k].points)
                out.cvs.push_back(Vec3(toController * Vec4(p * scale, 1.0)));
            out.degree = shape->curves[k].degree;
            out.periodic = shape->curves[k].periodic;
            const templates::Color c = shape->curves[k].color.value_or(color);
            out.color = Vec3(c.r, c.g, c.b);
            node.curves.push_back(std::move(out));
        }
    }
    for (const PendingClone& c : clones)
        cloneCurves(a, c);
}

} // namespace rs::rigging

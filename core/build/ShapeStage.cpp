// Finalize stage: gives every controller its curves from the manifest `shapes`
// entry (shape, size as largest extent, colour), matching wildcards like ctrls.*.
#include "build/RigAssembly.h"

#include <fnmatch.h>

#include <algorithm>

namespace rs::build {

namespace {

const templates::ShapeSpec* findSpec(const templates::TemplateManifest& manifest, const std::string& tag)
{
    if (const auto* exact = manifest.findShape(tag))
        return exact;
    for (const auto& spec : manifest.shapes)
        if (spec.key.find('*') != std::string::npos && fnmatch(spec.key.c_str(), tag.c_str(), 0) == 0)
            return &spec;
    return nullptr;
}

// A library shape sampled once per build: polylines and their largest extent.
struct SampledShape {
    std::vector<std::vector<Vec3>> curves;
    double extent = 0.0;
};

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

} // namespace

void applyShapes(RigAssembly& a)
{
    std::map<model::InstanceId, const InstanceRecord*> records;
    std::map<const templates::Shape*, SampledShape> sampled;
    for (const auto& r : a.records)
        records[r.instance->id] = &r;
    for (auto& node : a.rig.nodes) {
        if (node.kind != model::RigNodeKind::Controller)
            continue;
        auto record = records.find(node.owner);
        if (record == records.end())
            continue;
        const std::string tag = node.id.substr(node.id.find("::") + 2);
        const templates::ShapeSpec* spec = findSpec(*record->second->manifest, tag);
        const templates::Shape* shape = spec ? a.templates.shapes().find(spec->shape) : nullptr;
        if (!shape)
            shape = &fallbackShape();
        templates::Color color{1.0, 1.0, 0.0};
        if (spec && !spec->color.empty()) {
            if (auto parsed = templates::parseColor(spec->color))
                color = *parsed;
            else
                a.report(Severity::Warning, record->second->instance, "unknown colour '" + spec->color + "' in shapes." + spec->key);
        }
        auto cached = sampled.find(shape);
        if (cached == sampled.end())
            cached = sampled.emplace(shape, sample(*shape)).first;
        const SampledShape& polylines = cached->second;
        const double scale = (spec ? spec->size : 1.0) / (polylines.extent > 0.0 ? polylines.extent : 1.0);
        node.shape = shape->name;
        node.curves.clear();
        for (std::size_t k = 0; k < shape->curves.size(); ++k) {
            model::ControllerCurve out;
            out.points.reserve(polylines.curves[k].size());
            for (const Vec3& p : polylines.curves[k])
                out.points.push_back(p * scale);
            const templates::Color c = shape->curves[k].color.value_or(color);
            out.color = Vec3(c.r, c.g, c.b);
            node.curves.push_back(std::move(out));
        }
    }
}

} // namespace rs::build

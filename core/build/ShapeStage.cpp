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

double largestExtent(const templates::Shape& shape)
{
    Vec3 lo(1e300), hi(-1e300);
    for (const auto& curve : shape.curves)
        for (const Vec3& p : templates::evaluateCurve(curve)) {
            lo = glm::min(lo, p);
            hi = glm::max(hi, p);
        }
    const Vec3 extent = hi - lo;
    return std::max({extent.x, extent.y, extent.z});
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
        const double extent = largestExtent(*shape);
        const double scale = (spec ? spec->size : 1.0) / (extent > 0.0 ? extent : 1.0);
        node.shape = shape->name;
        node.curves.clear();
        for (const auto& curve : shape->curves) {
            model::ControllerCurve out;
            for (const Vec3& p : templates::evaluateCurve(curve))
                out.points.push_back(p * scale);
            const templates::Color c = curve.color.value_or(color);
            out.color = Vec3(c.r, c.g, c.b);
            node.curves.push_back(std::move(out));
        }
    }
}

} // namespace rs::build

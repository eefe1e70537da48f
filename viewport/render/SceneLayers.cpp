#include "SceneLayers.h"

#include <algorithm>

namespace rs::viewport {

namespace {

const glm::dvec3 kGuideColor(0.95, 0.55, 0.2);
const glm::dvec3 kSelectedColor(1.0, 1.0, 1.0);
const glm::dvec3 kCvColor(0.85, 0.45, 1.0);         // CV mode, as Maya's violet CVs
const glm::dvec3 kSelectedCvColor(1.0, 0.95, 0.2);
const glm::dvec3 kSkinColor(0.3, 0.9, 0.9);

void push(std::vector<Vertex>& out, const glm::dvec3& p, const glm::dvec3& c)
{
    out.push_back({float(p.x), float(p.y), float(p.z), float(c.x), float(c.y), float(c.z)});
}

class Layers {
public:
    explicit Layers(const std::vector<model::InstanceId>* only) : m_only(only) {}

    bool wants(model::InstanceId owner) const
    {
        return !m_only || std::binary_search(m_only->begin(), m_only->end(), owner);
    }

    void joints(const std::vector<SceneJoint>& joints, SceneLayer points, const glm::dvec3& lineColor,
                const glm::dvec3& pointColor, bool showSelection)
    {
        for (const auto& j : joints) {
            if (!wants(j.owner))
                continue;
            const bool selected = showSelection && j.selected;
            if (j.hasParent) {
                auto& lines = out[LinesLayer].block(j.owner);
                push(lines, j.parentPosition, selected ? kSelectedColor * 0.8 : lineColor);
                push(lines, j.position, selected ? kSelectedColor * 0.8 : lineColor);
            }
            push(out[points].block(j.owner), j.position, selected ? kSelectedColor : pointColor);
        }
    }

    void curves(const std::vector<SceneCurve>& curves, SceneLayer layer, bool showSelection)
    {
        for (const auto& c : curves) {
            if (!wants(c.owner) || c.points.size() < 2)
                continue;
            auto& block = out[layer].block(c.owner);
            const glm::dvec3 color = showSelection && c.selected ? kSelectedColor : c.color;
            for (std::size_t i = 1; i < c.points.size(); ++i) {
                push(block, c.points[i - 1], color);
                push(block, c.points[i], color);
            }
        }
    }

    void cvs(const std::vector<SceneCv>& cvs)
    {
        for (bool selected : {false, true}) // selected on top of unselected CVs at the same place
            for (const auto& cv : cvs)
                if (cv.selected == selected && wants(cv.owner))
                    push(out[CvPointsLayer].block(cv.owner), cv.position, selected ? kSelectedCvColor : kCvColor);
    }

    std::array<LayerBlocks, kSceneLayerCount> out;

private:
    const std::vector<model::InstanceId>* m_only;
};

} // namespace

std::vector<Vertex>& LayerBlocks::block(model::InstanceId owner)
{
    // Few owners per layer (one per instance), usually the last one again.
    if (!owners.empty() && owners.back() == owner)
        return blocks.back();
    const auto it = std::find(owners.begin(), owners.end(), owner);
    if (it != owners.end())
        return blocks[std::size_t(it - owners.begin())];
    owners.push_back(owner);
    return blocks.emplace_back();
}

std::array<LayerBlocks, kSceneLayerCount> sceneLayers(const Scene& scene, const std::vector<model::InstanceId>* only)
{
    Layers layers(only);
    if (scene.showGuides) {
        layers.joints(scene.guideJoints, GuidePointsLayer, kGuideColor * 0.8, kGuideColor, true);
        layers.joints(scene.mirrorJoints, MirrorPointsLayer, kGuideColor * 0.4, kGuideColor * 0.5, false);
    }
    layers.joints(scene.skinJoints, SkinPointsLayer, kSkinColor * 0.6, kSkinColor, false);
    layers.curves(scene.curves, CurvesLayer, true);
    layers.curves(scene.axes, CurvesLayer, false);
    layers.curves(scene.hulls, HullsLayer, false);
    layers.cvs(scene.cvs);
    return std::move(layers.out);
}

} // namespace rs::viewport

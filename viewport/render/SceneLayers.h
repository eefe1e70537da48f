#pragma once
// Internal to the renderer: a Scene's drawn layers as vertices grouped by the
// instance that owns them, so a change to one instance re-sends that
// instance's blocks only (Renderer keeps one persistent buffer per layer and
// each owner's range in it).
#include "../Scene.h"

#include <array>
#include <vector>

namespace rs::viewport {

struct Vertex {
    float x, y, z, r, g, b;
    bool operator==(const Vertex&) const = default;
};

// The scene layers, in draw order within Renderer's layer table.
enum SceneLayer { LinesLayer, CurvesLayer, SkinPointsLayer, MirrorPointsLayer, GuidePointsLayer, HullsLayer, CvPointsLayer,
                  kSceneLayerCount };

// One layer's vertices, one block per owner in the order owners first appear.
struct LayerBlocks {
    std::vector<model::InstanceId> owners;
    std::vector<std::vector<Vertex>> blocks;

    std::vector<Vertex>& block(model::InstanceId owner);
};

// Every scene layer; with `only` (sorted), the blocks of those owners alone.
std::array<LayerBlocks, kSceneLayerCount> sceneLayers(const Scene& scene, const std::vector<model::InstanceId>* only);

} // namespace rs::viewport

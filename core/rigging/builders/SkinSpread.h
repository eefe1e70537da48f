#pragma once
// Skin joints spread along a guide chain whatever its number of guide joints
// and controllers (spine.torso's skin_joints, neck.head's bones).
#include "base/Math.h"

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace rs::rigging::kit {

// How the joints share the chain (the bones_length option): Equal, the same
// length of guide chain each; Parametric, the same share of every guide
// segment (more joints where the guides are closer).
enum class BonesLength { Equal, Parametric };
// "equal" / "parametric"; nullopt for anything else.
std::optional<BonesLength> parseBonesLength(const std::string& text);

struct Spread {
    std::vector<Vec3> at;              // count + 1 points, points.front() to points.back()
    std::vector<std::size_t> segment;  // the guide segment each lies on (the guide before it)
};
// `count` + 1 points from the chain's first to its last point (world, metres).
Spread spreadAlong(const std::vector<Vec3>& points, std::size_t count, BonesLength mode);

} // namespace rs::rigging::kit

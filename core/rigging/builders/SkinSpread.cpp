#include "rigging/builders/SkinSpread.h"

#include "rigging/builders/BuilderKit.h"

#include <algorithm>
#include <cmath>

namespace rs::rigging::kit {

std::optional<BonesLength> parseBonesLength(const std::string& text)
{
    if (text == "equal")
        return BonesLength::Equal;
    if (text == "parametric")
        return BonesLength::Parametric;
    return std::nullopt;
}

Spread spreadAlong(const std::vector<Vec3>& points, std::size_t count, BonesLength mode)
{
    Spread spread;
    const std::size_t segments = points.size() > 1 ? points.size() - 1 : 0;
    for (std::size_t k = 0; k <= count; ++k) {
        const double share = count > 0 ? double(k) / double(count) : 0.0;
        if (mode == BonesLength::Equal || segments == 0) {
            const auto [p, s] = alongChain(points, share);
            spread.at.push_back(p);
            spread.segment.push_back(s);
            continue;
        }
        const double u = share * double(segments);
        const std::size_t s = std::min(static_cast<std::size_t>(std::floor(u)), segments - 1);
        spread.at.push_back(glm::mix(points[s], points[s + 1], u - double(s)));
        spread.segment.push_back(s);
    }
    return spread;
}

} // namespace rs::rigging::kit

#include "model/Mod.h"

#include <array>

namespace rs::model {

namespace {

constexpr std::array<const char*, kModKindCount> kKindNames{"space", "constraint", "parent", "hide", "plug", "drive", "vdag"};
constexpr std::array<const char*, 3> kPlugTypes{"float", "bool", "enum"};

} // namespace

const char* modKindName(ModKind kind)
{
    return kKindNames[static_cast<int>(kind)];
}

std::optional<ModKind> parseModKind(const std::string& name)
{
    for (int k = 0; k < kModKindCount; ++k)
        if (name == kKindNames[k])
            return static_cast<ModKind>(k);
    return std::nullopt;
}

const char* plugTypeName(PlugType type)
{
    return kPlugTypes[static_cast<int>(type)];
}

std::optional<PlugType> parsePlugType(const std::string& name)
{
    for (std::size_t k = 0; k < kPlugTypes.size(); ++k)
        if (name == kPlugTypes[k])
            return static_cast<PlugType>(k);
    return std::nullopt;
}

} // namespace rs::model

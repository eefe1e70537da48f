// The pieces the weight tools share (WeightToolsSupport.h).
#include "skin/WeightToolsSupport.h"

namespace rs::skin::detail {

namespace {

constexpr float kDrop = 1e-5f; // a share below this is no influence

} // namespace

std::vector<Influence> tidy(std::vector<Influence> in)
{
    std::erase_if(in, [](const Influence& i) { return !(i.weight > kDrop); });
    double sum = 0.0;
    for (const Influence& i : in)
        sum += i.weight;
    if (sum > 0.0)
        for (Influence& i : in)
            i.weight = float(i.weight / sum);
    std::sort(in.begin(), in.end(), [](const Influence& a, const Influence& b) {
        return a.weight != b.weight ? a.weight > b.weight : a.joint < b.joint;
    });
    return in;
}

// Writes `influences` to every file vertex welded into surface vertex `s`
// whose weights differ.
void emit(const WeightContext& c, const Welds& welds, std::uint32_t s, const std::vector<Influence>& influences,
          std::vector<VertexInfluences>& out)
{
    for (std::uint32_t k = welds.offsets[s]; k < welds.offsets[s + 1]; ++k) {
        const std::uint32_t v = welds.files[k];
        if (influencesOf(*c.weights, v) != influences)
            out.push_back({v, influences});
    }
}

// Blends `own` towards `goal` by `amount`, keeping locked joints' shares.
std::vector<Influence> blendUnlocked(const std::vector<Influence>& own, const std::vector<Influence>& goal, double amount,
                                     const WeightContext& c)
{
    std::vector<Influence> out;
    double locked = 0.0, unlockedGoal = 0.0;
    for (const Influence& i : own)
        if (c.isLocked(i.joint)) {
            locked += i.weight;
            out.push_back(i);
        }
    for (const Influence& i : goal)
        if (!c.isLocked(i.joint))
            unlockedGoal += i.weight;
    const double available = std::max(0.0, 1.0 - locked);
    std::vector<Influence> mixed;
    auto add = [&](std::uint32_t joint, double w) {
        for (Influence& m : mixed)
            if (m.joint == joint) {
                m.weight += float(w);
                return;
            }
        mixed.push_back({joint, float(w)});
    };
    double unlockedOwn = 0.0;
    for (const Influence& i : own)
        if (!c.isLocked(i.joint))
            unlockedOwn += i.weight;
    for (const Influence& i : own)
        if (!c.isLocked(i.joint))
            add(i.joint, (1.0 - amount) * i.weight);
    if (unlockedGoal > 0.0)
        for (const Influence& i : goal)
            if (!c.isLocked(i.joint))
                add(i.joint, amount * i.weight * (unlockedOwn > 0.0 ? unlockedOwn / unlockedGoal : 1.0 / unlockedGoal));
    double sum = 0.0;
    for (const Influence& m : mixed)
        sum += m.weight;
    if (sum > 0.0)
        for (const Influence& m : mixed)
            out.push_back({m.joint, float(m.weight / sum * available)});
    return tidy(out);
}

} // namespace rs::skin::detail

#include "io/ManifestReader.h"
#include "templates/Structure.h"

#include <gtest/gtest.h>

using namespace rs;
using namespace rs::templates;
using model::JointId;

namespace {

// root(1) -> 2 -> 3 -> fork: 4 (untagged) -> 5, and 6 tagged "heel".
model::TemplateInstance limb()
{
    model::TemplateInstance i;
    i.id = 1;
    i.name = "leg";
    i.joints = {{1, 0, {}, {}, {}}, {2, 1, {}, {}, {}}, {3, 2, {}, {}, {}}, {4, 3, {}, {}, {}}, {5, 4, {}, {}, {}}, {6, 3, {}, {"heel"}, {}}};
    return i;
}

TemplateManifest manifest(const std::string& structure)
{
    auto r = io::readManifestText("structure:\n" + structure, "m.yml", "leg", "test");
    EXPECT_TRUE(r.ok()) << formatAll(r.diagnostics());
    return r.take();
}

std::vector<JointId> ids(std::initializer_list<JointId> list) { return list; }

} // namespace

TEST(Structure, ResolvesDepthAddressesAlongTheSingleChildChain)
{
    const auto m = manifest("  root: .\n  knee: /1\n  last: /-1\n  all: /*\n");
    const auto instance = limb();
    StructureResolver r(m, instance);
    EXPECT_EQ(*r.tag("root"), ids({1}));
    EXPECT_EQ(*r.tag("knee"), ids({2}));
    // The tagged heel is off-chain, so joint 3 has one chain child (4) and the chain runs to 5.
    EXPECT_EQ(*r.tag("all"), ids({1, 2, 3, 4, 5}));
    EXPECT_EQ(*r.tag("last"), ids({5}));
}

TEST(Structure, StopsTheChainAtAForkWithoutUsingSiblingOrder)
{
    auto instance = limb();
    instance.joints[5].tags.clear(); // joint 3 now has two untagged children
    const auto m = manifest("  all: /*\n");
    StructureResolver r(m, instance);
    EXPECT_EQ(*r.tag("all"), ids({1, 2, 3}));
}

TEST(Structure, ResolvesExplicitTagsSlicesAndConcatenation)
{
    const auto m = manifest("  chain: /*\n  heel:\n  base: chain[:-1]\n  tip: chain[1:]\n  end: chain[-1]\n"
                            "  mix: heel+chain[0]\n  every: chain[*]\n");
    const auto instance = limb();
    StructureResolver r(m, instance);
    EXPECT_EQ(*r.tag("heel"), ids({6}));
    EXPECT_EQ(*r.tag("base"), ids({1, 2, 3, 4}));
    EXPECT_EQ(*r.tag("tip"), ids({2, 3, 4, 5}));
    EXPECT_EQ(*r.tag("end"), ids({5}));
    EXPECT_EQ(*r.tag("mix"), ids({6, 1}));
    EXPECT_EQ(*r.tag("every"), ids({1, 2, 3, 4, 5}));
    EXPECT_EQ(*r.address("chain[2:4]"), ids({3, 4}));
}

TEST(Structure, ReportsUnknownTagsBadIndicesAndCycles)
{
    // Built by hand: the manifest reader refuses the a <-> b cycle at load time.
    TemplateManifest m;
    m.structure = {{"chain", "/*"}, {"a", "b"}, {"b", "a"}, {"missing", ""}, {"far", "/9"}};
    const auto instance = limb();
    StructureResolver r(m, instance);
    auto errorOf = [](const Result<std::vector<model::JointId>>& joints) {
        EXPECT_FALSE(joints);
        return firstError(joints.diagnostics());
    };
    EXPECT_EQ(errorOf(r.tag("nope")), "unknown structure tag 'nope'");
    EXPECT_EQ(errorOf(r.tag("missing")), "no guide joint is tagged 'missing'");
    EXPECT_EQ(errorOf(r.tag("far")), "address '/9': index [9] is out of range (5 joints)");
    EXPECT_NE(errorOf(r.tag("a")).find("refers to itself"), std::string::npos);
    EXPECT_EQ(errorOf(r.address("chain[1")), "missing ']' in 'chain[1'");
}

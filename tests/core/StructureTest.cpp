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
    std::string error;
    EXPECT_FALSE(r.tag("nope", &error));
    EXPECT_EQ(error, "unknown structure tag 'nope'");
    EXPECT_FALSE(r.tag("missing", &error));
    EXPECT_EQ(error, "no guide joint is tagged 'missing'");
    EXPECT_FALSE(r.tag("far", &error));
    EXPECT_EQ(error, "address '/9': index [9] is out of range (5 joints)");
    EXPECT_FALSE(r.tag("a", &error));
    EXPECT_NE(error.find("refers to itself"), std::string::npos) << error;
    EXPECT_FALSE(r.address("chain[1", &error));
    EXPECT_EQ(error, "missing ']' in 'chain[1'");
}

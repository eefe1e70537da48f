// Mikan's common options every template has (issue 22 item 1), on built rigs:
// `virtual_parent` hangs a template's virtual hierarchy (pickwalk, the export
// skeleton) from the closest node of the template instance it names.
#include "EvalTestSupport.h"
#include "model/Skeleton.h"

#include <gtest/gtest.h>

namespace rs {
namespace {

model::GuideDocument propWithVirtualParent(const std::string& value)
{
    model::GuideDocument guide = test::loadSample("prop");
    guide.instance(guide.instanceNamed("antenna")->id)->options["virtual_parent"] = Value(value);
    return guide;
}

const model::RigNode& node(const test::PosedRig& r, const std::string& id) { return r.rig.nodes[r.index(id)]; }

} // namespace

TEST(CommonOptions, VirtualParentHangsTheVirtualHierarchyFromTheNamedTemplatesClosestNode)
{
    {
        test::PosedRig r("prop");
        ASSERT_TRUE(r.ok());
        EXPECT_EQ(node(r, "antenna::ctrls.0").virtualParent, r.index("lid::ctrls.xform")) << "by default: the lid it hangs on";
        EXPECT_EQ(node(r, "antenna::skin.0").virtualParent, r.index("lid::skin.xform"));
    }
    test::PosedRig r(propWithVirtualParent("chest"));
    ASSERT_TRUE(r.ok());
    EXPECT_TRUE(r.rig.diagnostics.empty()) << formatAll(r.rig.diagnostics);
    EXPECT_EQ(node(r, "antenna::ctrls.0").virtualParent, r.index("chest::ctrls.xform")) << "pickwalk goes up to the chest";
    EXPECT_EQ(node(r, "antenna::skin.0").virtualParent, r.index("chest::skin.xform")) << "the export skeleton too";
    EXPECT_EQ(node(r, "antenna::ctrls.1").virtualParent, r.index("antenna::ctrls.0")) << "the chain inside is kept";
    EXPECT_EQ(node(r, "antenna::roots.0").parent, r.index("lid::ctrls.xform")) << "the physical hierarchy is unchanged";
    auto skeleton = model::extractSkeleton(r.rig);
    ASSERT_TRUE(skeleton.ok()) << formatAll(skeleton.diagnostics());
}

TEST(CommonOptions, AVirtualParentThatNamesNoInstanceOrItselfIsReportedAndTheDefaultKept)
{
    for (const auto& [value, said] : {std::pair<std::string, std::string>{"nothing", "virtual_parent: no instance named 'nothing'"},
                                      {"antenna", "(a loop)"}}) {
        SCOPED_TRACE(value);
        test::PosedRig r(propWithVirtualParent(value));
        ASSERT_TRUE(r.ok());
        const std::string log = formatAll(r.rig.diagnostics);
        EXPECT_NE(log.find(said), std::string::npos) << log;
        EXPECT_EQ(node(r, "antenna::ctrls.0").virtualParent, r.index("lid::ctrls.xform"));
    }
}

} // namespace rs

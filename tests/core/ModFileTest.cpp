// Mods in the guide file and through a rebuild: a mod whose node is missing is
// a build warning with its file:line and a typed subject, and is kept; a
// malformed mod is an error at file:line:col; mods survive an instance rename
// and a save / reopen; an incremental rebuild equals a full one.
#include "core/IncrementalCheck.h"
#include "ModsTestSupport.h"

#include "edit/GuideEdits.h"
#include "io/GuideFile.h"
#include "io/RigDump.h"
#include "rigging/BuildCache.h"

#include <gtest/gtest.h>

using namespace rs;

namespace {

constexpr model::InstanceId kArm = 4;
const char* const kModsGuide = "Mods/biped/guide.yml";

// The diagnostics of a build that mention `text`.
std::vector<Diagnostic> about(const model::Rig& rig, const std::string& text)
{
    std::vector<Diagnostic> out;
    for (const Diagnostic& d : rig.diagnostics)
        if (d.message.find(text) != std::string::npos)
            out.push_back(d);
    return out;
}

// The mod stage's warnings ("space mod of 'arm.L': ...", "global hide mod: ...").
std::vector<Diagnostic> modWarnings(const model::Rig& rig)
{
    std::vector<Diagnostic> out;
    for (const Diagnostic& d : rig.diagnostics)
        if (d.message.find(" mod of '") != std::string::npos || d.message.find(" mod: ") != std::string::npos)
            out.push_back(d);
    return out;
}

std::string rigDumpWithoutDiagnostics(const model::Rig& rig)
{
    const std::string dump = io::writeRigDump(rig);
    return dump.substr(0, dump.find("\ndiagnostics:"));
}

} // namespace

TEST(Mods, TheTestGuideReadsWithEveryKindAndBuildsWithoutWarnings)
{
    const model::GuideDocument guide = test::loadGuide(kModsGuide);
    std::set<model::ModKind> kinds;
    for (const model::Mod& mod : guide.mods) {
        kinds.insert(mod.kind());
        EXPECT_GT(mod.where.line, 0);
        EXPECT_NE(mod.where.file.find("guide.yml"), std::string::npos);
    }
    EXPECT_EQ(kinds.size(), std::size_t(model::kModKindCount));
    const model::Rig rig = rigging::buildRig(guide, test::builtinTemplates());
    EXPECT_TRUE(modWarnings(rig).empty()) << formatAll(rig.diagnostics);
    EXPECT_FALSE(hasErrors(rig.diagnostics)) << formatAll(rig.diagnostics);
}

TEST(Mods, EachKindWithAMissingTargetIsAWarningAtItsLineWithASubjectAndIsKept)
{
    const std::string text = test::readText(test::samplePath("biped")) +
        "mods:\n"
        "  - instance: arm\n    space: {node: ctrls.nope, target: 'spine::ctrls.hips'}\n"
        "  - constraint: {kind: parent, node: 'arm.L::roots.ik', targets: ['spine::ctrls.nope']}\n"
        "  - parent: {node: 'arm.L::ctrls.nope', parent: 'spine::ctrls.hips'}\n"
        "  - hide: ['ghost::ctrls.fk.0']\n"
        "  - plug: {channel: 'arm.L::ctrls.nope@fist', default: 1}\n"
        "  - drive: {driver: 'arm.L::ctrls.fk.1@nope', driven: 'hand.L::ctrls.hand@rx', keys: {0: 0, 90: 30}}\n"
        "  - vdag: {node: 'arm::ctrls.ik', parent: 'spine::ctrls.hips'}\n";
    auto read = io::readGuideText(text, "bad.yml");
    ASSERT_TRUE(read.ok()) << formatAll(read.diagnostics());
    const model::GuideDocument guide = read.take();
    ASSERT_EQ(guide.mods.size(), 7u);
    const model::Rig rig = rigging::buildRig(guide, test::builtinTemplates());
    EXPECT_FALSE(hasErrors(rig.diagnostics)) << formatAll(rig.diagnostics);
    const int firstLine = int(std::count(text.begin(), text.begin() + text.find("mods:"), '\n')) + 2;
    const std::pair<const char*, std::string> expected[] = {
        {"space mod of 'arm.L'", "'arm.L::ctrls.nope'"}, {"global constraint mod", "'spine::ctrls.nope'"},
        {"global parent mod", "'arm.L::ctrls.nope'"},    {"global hide mod", "no instance 'ghost'"},
        {"global plug mod", "'arm.L::ctrls.nope@fist'"}, {"global drive mod", "no channel 'nope'"},
        {"global vdag mod", "name one, e.g. arm.L::ctrls.ik"}};
    for (std::size_t k = 0; k < std::size(expected); ++k) {
        const auto found = about(rig, expected[k].first);
        ASSERT_FALSE(found.empty()) << expected[k].first << "\n" << formatAll(rig.diagnostics);
        const Diagnostic& d = found.front();
        EXPECT_EQ(d.severity, Severity::Warning);
        EXPECT_NE(d.message.find(expected[k].second), std::string::npos) << d.message;
        EXPECT_EQ(d.where.file, "bad.yml");
        EXPECT_EQ(d.where.line, firstLine + int(k) + (k > 0 ? 1 : 0)) << d.format(); // the first mod takes two lines
        if (k != 3) { // a ghost instance has nothing to select
            EXPECT_FALSE(d.subject.isNone()) << d.format();
        }
    }
    EXPECT_EQ(about(rig, "space mod of 'arm.R'").front().subject, Subject::ofInstance(kArm, "R"));
    // Nothing changed in the rig, and every mod is still in the guide, written back as read.
    EXPECT_EQ(rigDumpWithoutDiagnostics(rig), rigDumpWithoutDiagnostics(rigging::buildRig(test::loadSample("biped"), test::builtinTemplates())));
    const std::string written = io::writeGuideText(guide);
    auto again = io::readGuideText(written, "again.yml");
    ASSERT_TRUE(again.ok()) << formatAll(again.diagnostics());
    EXPECT_EQ(again->mods, guide.mods);
    EXPECT_EQ(io::writeGuideText(*again), written);
}

TEST(Mods, AMalformedModIsAnErrorAtItsLineAndColumn)
{
    const std::string base = test::readText(test::samplePath("biped")) + "mods:\n";
    const int line = int(std::count(base.begin(), base.end(), '\n')) + 1;
    const std::pair<std::string, std::string> cases[] = {
        {"  - spin: {node: 'arm.L::ctrls.ik'}\n", "unknown mod kind 'spin'"},
        {"  - hide: [ctrls.ik]\n", "a global mod names a node as instance::tag"},
        {"  - plug: {channel: 'arm.L::ctrls.ik', default: 1}\n", "needs a channel"},
        {"  - vdag: {node: 'arm.L::ctrls.ik@tx', parent: 'spine::ctrls.hips'}\n", "it takes a node"},
        {"  - drive: {driver: 'a.L::c@rz', driven: 'b.L::c@rx', keys: [1, 2]}\n", "keys"},
        {"  - constraint: {kind: twist, node: 'a::b', targets: ['c::d']}\n", "is not one of parent, point"},
        {"  - constraint: {node: 'a::b', targets: ['c::d'], weights: [1, 2]}\n", "one weight per target"},
        {"  - plug: {channel: 'a::b@c', type: enum}\n", "needs 'labels'"},
        {"  - space: {node: 'a::b'}\n", "needs 'target'"},
        {"  - instance: arm\n    space: {node: ctrls.ik, target: 'a::b'}\n    hide: [ctrls.pole]\n", "a mod has one kind"}};
    for (const auto& [mod, message] : cases) {
        auto read = io::readGuideText(base + mod, "bad.yml");
        ASSERT_FALSE(read.ok()) << mod;
        const Diagnostic* error = nullptr;
        for (const Diagnostic& d : read.diagnostics())
            if (d.severity == Severity::Error && !error) error = &d;
        ASSERT_TRUE(error) << mod;
        EXPECT_NE(error->message.find(message), std::string::npos) << error->format();
        EXPECT_EQ(error->where.file, "bad.yml");
        EXPECT_GE(error->where.line, line) << error->format();
        EXPECT_GT(error->where.column, 0) << error->format();
    }
    auto text = io::readModText(test::loadSample("biped"), {}, "hide: [\n", "panel");
    ASSERT_FALSE(text.ok());
    EXPECT_EQ(text.diagnostics().front().where.file, "panel");
    EXPECT_GT(text.diagnostics().front().where.line, 0);
}

TEST(Mods, AGuideWithoutModsIsWrittenAsBefore)
{
    for (const char* sample : {"biped", "quadruped", "prop", "face", "claw", "cart", "strider"}) {
        const std::string text = test::readText(test::samplePath(sample));
        auto read = io::readGuideText(text, sample);
        ASSERT_TRUE(read.ok());
        EXPECT_TRUE(read->mods.empty());
        const std::string written = io::writeGuideText(*read);
        // The same but for a sample's own first line (its description).
        EXPECT_EQ(written.substr(written.find('\n')), text.substr(text.find('\n'))) << sample;
    }
}

TEST(Mods, AModSurvivesAnInstanceRenameAndASaveAndReopen)
{
    model::GuideDocument guide = test::loadGuide(kModsGuide);
    edit::History history(guide);
    ASSERT_TRUE(test::succeeded(edit::renameInstance(history, kArm, "limb")));
    ASSERT_TRUE(test::succeeded(edit::renameInstance(history, 5, "shin"))); // the leg: named by other mods
    const model::Rig renamed = rigging::buildRig(guide, test::builtinTemplates());
    EXPECT_TRUE(modWarnings(renamed).empty()) << formatAll(renamed.diagnostics);
    // Every mod still applies: the renamed arm's new space, its hidden pin, the hand's drive and virtual parent.
    const auto at = [&](const std::string& id) -> const model::RigNode& { return renamed.nodes[*renamed.findPath(id)]; };
    ASSERT_TRUE(renamed.findPath("limb.R::ctrls.ik"));
    EXPECT_EQ(at("limb.R::ctrls.ik").attribute("space")->labels.back(), "foot");
    EXPECT_TRUE(at("limb.L::ctrls.pin").hidden);
    EXPECT_EQ(at("hand.L::ctrls.hand").virtualParent, *renamed.findPath("limb.L::ctrls.ik"));
    EXPECT_EQ(std::count_if(renamed.constraints.begin(), renamed.constraints.end(),
                            [](const model::RigConstraint& c) { return c.kind() == model::ConstraintKind::DrivenKey; }),
              3); // the hand's drive on each side, and the switch's connection
    const std::string path = test::temporaryPath("mods-renamed.yml");
    ASSERT_TRUE(test::succeeded(io::saveGuideFile(guide, path)));
    const std::string saved = test::readText(path);
    EXPECT_NE(saved.find("instance: limb"), std::string::npos);
    EXPECT_NE(saved.find("shin::ctrls.ik"), std::string::npos);
    auto reopened = io::readGuideFile(path);
    ASSERT_TRUE(reopened.ok()) << formatAll(reopened.diagnostics());
    EXPECT_EQ(reopened->mods, guide.mods);
    EXPECT_EQ(rigDumpWithoutDiagnostics(rigging::buildRig(*reopened, test::builtinTemplates())), rigDumpWithoutDiagnostics(renamed));
}

TEST(Mods, AModOfADeletedInstanceIsReportedKeptAndAppliesAgainWhenItIsBack)
{
    model::GuideDocument guide = test::loadGuide(kModsGuide);
    const std::string full = io::writeRigDump(rigging::buildRig(guide, test::builtinTemplates()));
    edit::History history(guide);
    const std::size_t mods = guide.mods.size();
    ASSERT_TRUE(test::succeeded(edit::removeInstance(history, 11))); // the hand (and the fingers below it)
    const model::Rig without = rigging::buildRig(guide, test::builtinTemplates());
    EXPECT_FALSE(hasErrors(without.diagnostics)) << formatAll(without.diagnostics);
    EXPECT_FALSE(about(without, "no instance 'hand'").empty()) << formatAll(without.diagnostics);
    EXPECT_EQ(guide.mods.size(), mods);
    const std::string written = io::writeGuideText(guide);
    EXPECT_NE(written.find("hand.L::ctrls.hand"), std::string::npos); // written with the name it had
    history.undo();
    EXPECT_EQ(io::writeRigDump(rigging::buildRig(guide, test::builtinTemplates())), full);
}

TEST(Mods, AnIncrementalRebuildEqualsAFullBuildWithMods)
{
    model::GuideDocument guide = test::loadGuide(kModsGuide);
    rigging::BuildCache cache;
    auto compare = [&](const std::string& what) { test::buildAndCompare(guide, cache, what); };
    compare("first");
    compare("second");
    for (const auto& instance : std::vector<model::TemplateInstance>(guide.instances())) {
        guide.instance(instance.id)->joints.front().local.translate.y += 0.01;
        compare("move " + instance.name);
    }
    guide.mods.pop_back();
    compare("a mod removed");
    guide.mods.push_back(test::modFromText(guide, "arm", "hide: [ctrls.pin]"));
    compare("a mod added");
}

TEST(Mods, EveryKindsSampleReadsAndWritesBackAsItsText)
{
    const model::GuideDocument guide = test::loadSample("biped");
    for (int k = 0; k < model::kModKindCount; ++k)
        for (const bool ofInstance : {true, false}) {
            const auto kind = model::ModKind(k);
            const model::ModInstance owner = ofInstance ? model::ModInstance{kArm, "arm"} : model::ModInstance{};
            auto mod = io::readModText(guide, owner, io::modSample(kind, ofInstance), "sample");
            ASSERT_TRUE(mod.ok()) << model::modKindName(kind) << "\n" << formatAll(mod.diagnostics());
            EXPECT_EQ(mod->kind(), kind);
            EXPECT_EQ(mod->isGlobal(), !ofInstance);
            // Its text reads back to the same mod.
            auto again = io::readModText(guide, owner, io::writeModText(guide, *mod), "again");
            ASSERT_TRUE(again.ok()) << io::writeModText(guide, *mod) << formatAll(again.diagnostics());
            EXPECT_EQ(*again, *mod);
        }
}

TEST(Mods, HideTakesMikansOneLineFormOfSeveralNodes)
{
    const model::GuideDocument guide = test::loadSample("biped");
    auto mod = io::readModText(guide, {}, "hide: arm.L::ctrls.pin arm.R::ctrls.pin");
    ASSERT_TRUE(mod.ok()) << formatAll(mod.diagnostics());
    const auto& hide = std::get<model::HideMod>(mod->settings);
    ASSERT_EQ(hide.nodes.size(), 2u);
    EXPECT_EQ(hide.nodes[1].instance.id, kArm);
    EXPECT_EQ(hide.nodes[1].branch, std::optional<std::string>("R"));
    EXPECT_EQ(io::writeModText(guide, *mod), "hide: [\"arm.L::ctrls.pin\", \"arm.R::ctrls.pin\"]\n");
}

// The re-fit of changed meshes as a job (issue 20 item 5, session/RefitJob.h):
// with a runner set (the editor's worker thread) opening a guide hands the
// job over instead of blocking; run on another thread it gives the record the
// synchronous re-fit gives; a job the guide changed under is stale and never
// applied; per vertex it says which step placed its weights.
#include "SessionSkinFixture.h"
#include "TestSupport.h"

#include "session/Session.h"

#include <gtest/gtest.h>

#include <optional>
#include <thread>

using namespace rs;
using namespace rs::test::sessionskin;

namespace {

// A guide bound to the sleeve, and its chunks as saved beside its weights.
struct Saved {
    model::GuideDocument guide;
    std::vector<skin::SkinChunk> chunks;
    model::Mesh sleeve;
    Saved()
    {
        Fixture f;
        EXPECT_TRUE(test::succeeded(f.s.addModel(kArm)));
        f.bind();
        guide = f.s.document();
        chunks = f.s.bindingChunks();
        sleeve = f.files.files[kArm].meshes[0];
    }
};

// The sleeve remeshed with two more rings.
void remesh(Fixture& f, const Saved& saved)
{
    f.files.files[kArm].meshes[0] = tube("sleeve", saved.sleeve.positions.front(), saved.sleeve.positions.back(), 18);
    f.s.setSavedChunks(saved.chunks);
}

} // namespace

TEST(SessionRefitJob, ARunnerGetsTheJobAndAWorkerThreadsResultEqualsTheSynchronousOne)
{
    const Saved saved;
    Fixture sync; // the CLI's way: prepare, run and apply on open
    remesh(sync, saved);
    sync.s.replaceDocument(saved.guide);
    ASSERT_EQ(sync.s.document().bindings[0].vertexCount, 216u);
    ASSERT_EQ(sync.s.history().undoText(), "Re-fit weights of mesh 'sleeve'");

    Fixture f;
    remesh(f, saved);
    std::vector<session::RefitJob> handed;
    f.s.setRefitRunner([&](session::RefitJob job) { handed.push_back(std::move(job)); });
    f.s.replaceDocument(saved.guide);
    ASSERT_EQ(handed.size(), 1u) << "the open hands the re-fit over";
    EXPECT_EQ(f.s.history().size(), 0u) << "and applies nothing itself";
    EXPECT_EQ(f.s.document().bindings[0].vertexCount, 192u);
    ASSERT_EQ(handed[0].items.size(), 1u);
    EXPECT_TRUE(f.s.isCurrent(handed[0]));

    session::RefitJob job = std::move(handed[0]);
    Status ran = Status::success();
    std::thread worker([&] { ran = job.run(); });
    worker.join();
    ASSERT_TRUE(test::succeeded(ran));
    const std::vector<session::VertexRoute> routes = job.routes(0);
    ASSERT_EQ(routes.size(), 216u);
    EXPECT_EQ(std::count(routes.begin(), routes.end(), session::VertexRoute::OneToOne), 0) << "another topology: nothing 1:1";
    EXPECT_EQ(std::size_t(std::count(routes.begin(), routes.end(), session::VertexRoute::Inpainted)), job.refits[0]->report.inpainted);
    auto applied = f.s.applyRefit(std::move(job));
    ASSERT_TRUE(applied.ok()) << formatAll(applied.diagnostics());
    ASSERT_EQ(applied->size(), 1u);
    EXPECT_EQ(f.s.history().undoText(), "Re-fit weights of mesh 'sleeve'");
    EXPECT_TRUE(f.s.document().bindings[0] == sync.s.document().bindings[0]) << "the worker's record is the synchronous one";
    EXPECT_TRUE(f.saidSomething("(192 vertices then, 216 now): its weights were re-fitted"));
}

TEST(SessionRefitJob, AJobTheGuideChangedUnderIsStaleAndNeverApplied)
{
    const Saved saved;
    Fixture f;
    remesh(f, saved);
    std::vector<session::RefitJob> handed;
    f.s.setRefitRunner([&](session::RefitJob job) { handed.push_back(std::move(job)); });
    f.s.replaceDocument(saved.guide);
    ASSERT_EQ(handed.size(), 1u);
    session::RefitJob job = std::move(handed[0]);
    ASSERT_TRUE(test::succeeded(job.run()));

    const model::InstanceId renamed = f.s.document().instances().back().id;
    ASSERT_TRUE(test::succeeded(f.s.renameInstance(renamed, "renamed_meanwhile"))); // an edit while it ran
    EXPECT_FALSE(f.s.isCurrent(job));
    const model::GuideDocument edited = f.s.document();
    auto stale = f.s.applyRefit(std::move(job));
    ASSERT_FALSE(stale.ok());
    EXPECT_NE(formatAll(stale.diagnostics()).find("the result is stale"), std::string::npos);
    EXPECT_TRUE(f.s.document() == edited) << "nothing applied over the newer edit";
    EXPECT_EQ(f.s.history().size(), 1u);

    // Prepared again from the guide as it is now, it applies after the edit.
    std::optional<session::RefitJob> again = f.s.prepareRefit();
    ASSERT_TRUE(again);
    ASSERT_TRUE(test::succeeded(again->run()));
    ASSERT_TRUE(f.s.applyRefit(std::move(*again)).ok());
    EXPECT_EQ(f.s.document().bindings[0].vertexCount, 216u);
    EXPECT_EQ(f.s.document().instance(renamed)->name, "renamed_meanwhile");
    EXPECT_EQ(f.s.history().size(), 2u);
    EXPECT_FALSE(f.s.prepareRefit()) << "nothing is left to re-fit";
}

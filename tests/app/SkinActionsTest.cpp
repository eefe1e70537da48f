// Issue 19 in the editor: Guide > Add Model, Skin > Bind on a worker thread
// (progress, Cancel keeps the previous weights, one undo step), the weights
// saved beside the guide and loaded on open, and a model file changed on disk
// offered for reloading.
#include "EditorTestSupport.h"

#include "LogPanel.h"
#include "io/WeightsFile.h"

#include <QAction>
#include <QFile>
#include <QListWidgetItem>

#include <fstream>

using namespace rs;
using namespace rs::test;


TEST(SkinActions, AddModelThenBindOnAWorkerThreadIsOneUndoStep)
{
    Editor e;
    const QString sleeve = writeSleeve(e.window, "sleeve-bind.obj", 12);
    ASSERT_TRUE(e.window.addModel(sleeve));
    EXPECT_EQ(e.window.session().history().undoText(), "Add model sleeve-bind.obj");
    ASSERT_EQ(e.window.session().characterMeshes().size(), 1u);
    EXPECT_FALSE(e.window.addModel(sleeve)) << "the same file twice is refused";
    EXPECT_FALSE(e.window.addModel(QString::fromStdString(outputPath("no-such-model.obj"))));

    e.window.action("bindSkin")->trigger();
    EXPECT_TRUE(e.window.isBinding() || !e.window.session().document().bindings.empty());
    ASSERT_TRUE(QTest::qWaitFor([&] { return !e.window.isBinding(); }, 20000));
    ASSERT_EQ(e.window.session().document().bindings.size(), 1u);
    EXPECT_EQ(e.window.session().history().undoText(), "Bind skin");
    const auto& mesh = e.window.session().characterMeshes()[0];
    ASSERT_TRUE(mesh.weights);
    // OBJ faces do not share vertices once imported (Assimp keeps one per face corner): 11 x 10 quads.
    EXPECT_EQ(mesh.weights->vertexCount(), 440u);
    EXPECT_TRUE(logSays(e.window, "Bound 440 vertices to"));
    EXPECT_TRUE(e.window.action("bindSkin")->isEnabled());

    e.window.session().history().undo();
    EXPECT_TRUE(e.window.session().document().bindings.empty());
    EXPECT_FALSE(e.window.session().characterMeshes()[0].weights);
}

TEST(SkinActions, CancelKeepsThePreviousWeights)
{
    Editor e;
    ASSERT_TRUE(e.window.addModel(writeSleeve(e.window, "sleeve-cancel.obj", 12)));
    e.window.action("maxInfluences:2")->trigger();
    e.window.bindSkin();
    ASSERT_TRUE(QTest::qWaitFor([&] { return !e.window.isBinding(); }, 20000));
    const auto before = e.window.session().document().bindings;
    ASSERT_EQ(before.size(), 1u);
    for (std::size_t v = 0; v < before[0].weights.vertexCount(); ++v)
        EXPECT_LE(before[0].weights.end(v) - before[0].weights.begin(v), 2) << "Skin > Max Influences applies";
    const std::size_t steps = e.window.session().history().size();

    e.window.action("bindMethod:closest")->trigger();
    e.window.bindSkin();
    ASSERT_TRUE(e.window.isBinding());
    e.window.cancelBind(); // before the worker's result is taken: cancelled whatever the worker got to
    ASSERT_TRUE(QTest::qWaitFor([&] { return !e.window.isBinding(); }, 20000));
    EXPECT_TRUE(e.window.session().document().bindings == before);
    EXPECT_EQ(e.window.session().history().size(), steps);
    EXPECT_TRUE(logSays(e.window, "Bind cancelled; the previous weights are kept"));
}

TEST(SkinActions, WeightsAreSavedBesideTheGuideAndComeBackOnOpen)
{
    Editor e;
    ASSERT_TRUE(e.window.addModel(writeSleeve(e.window, "sleeve-save.obj", 12)));
    e.window.bindSkin();
    ASSERT_TRUE(QTest::qWaitFor([&] { return !e.window.isBinding(); }, 20000));
    const auto bound = e.window.session().document().bindings;
    ASSERT_EQ(bound.size(), 1u);
    const QString guide = QString::fromStdString(outputPath("skinned-guide.yml"));
    QFile::remove(QString::fromStdString(io::weightsPathFor(guide.toStdString())));
    ASSERT_TRUE(e.window.saveFile(guide));
    EXPECT_TRUE(QFile::exists(QString::fromStdString(io::weightsPathFor(guide.toStdString()))));

    ASSERT_TRUE(e.window.openFile(kSample));
    EXPECT_TRUE(e.window.session().document().bindings.empty());
    ASSERT_TRUE(e.window.openFile(guide));
    EXPECT_TRUE(e.window.session().document().bindings == bound);
    e.window.buildRig();
    ASSERT_EQ(e.window.session().characterMeshes().size(), 1u);
    EXPECT_TRUE(e.window.session().characterMeshes()[0].weights) << "loaded weights skin the mesh on the new rig";
}

TEST(SkinActions, AModelChangedOnDiskIsOfferedAndItsWeightsRefitted)
{
    Editor e;
    const QString sleeve = writeSleeve(e.window, "sleeve-change.obj", 12);
    ASSERT_TRUE(e.window.addModel(sleeve));
    e.window.bindSkin();
    ASSERT_TRUE(QTest::qWaitFor([&] { return !e.window.isBinding(); }, 20000));
    const model::MeshBinding bound = e.window.session().document().bindings.at(0);
    QStringList asked;
    e.window.setReloadPrompt([&](const QString& file) {
        asked.push_back(file);
        return true;
    });
    writeSleeve(e.window, "sleeve-change.obj", 14); // another program saves a longer sleeve
    ASSERT_TRUE(QTest::qWaitFor([&] { return !asked.isEmpty(); }, 10000)) << "a changed file is offered for reloading";
    EXPECT_EQ(asked.front(), sleeve);
    ASSERT_TRUE(QTest::qWaitFor([&] { return e.window.session().document().bindings.at(0).vertexCount == 520u; }, 5000));
    EXPECT_FALSE(e.window.session().characterMeshes()[0].changed);
    EXPECT_TRUE(e.window.session().characterMeshes()[0].weights) << "re-fitted from the mesh as it was bound";
    EXPECT_TRUE(logSays(e.window, "changed since it was bound (440 vertices then, 520 now): its weights were re-fitted"));
    EXPECT_EQ(e.window.session().history().undoText(), "Re-fit weights of mesh 'sleeve'");
    e.window.action("undo")->trigger();
    EXPECT_TRUE(e.window.session().characterMeshes()[0].changed);
    EXPECT_FALSE(e.window.session().characterMeshes()[0].weights);
    EXPECT_TRUE(e.window.session().document().bindings.at(0) == bound) << "undo brings the old weights back, kept, not applied";
}

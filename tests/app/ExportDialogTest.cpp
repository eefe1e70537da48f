// The Export dialog driven through its real widgets (issue 6).
#include "EditorTestSupport.h"
#include "ExportDialog.h"

#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QSpinBox>

#include <fstream>

using namespace rs;

TEST(ExportDialog, ExportsTheBuiltRigWithTheChosenPresetAndOptions)
{
    test::Editor editor;
    auto& w = editor.window;
    w.action("exportRig")->trigger();
    widgets::ExportDialog* dialog = w.exportDialog();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(dialog));

    auto* path = dialog->findChild<QLineEdit*>("exportPath");
    auto* button = dialog->findChild<QPushButton*>("exportButton");
    ASSERT_TRUE(path && button);
    QTest::keyClicks(path, "rig.obj");
    EXPECT_FALSE(button->isEnabled()) << "only .glb, .gltf and .fbx";

    const std::string fbx = test::outputPath("dialog-unreal.fbx");
    std::filesystem::remove(fbx);
    path->setText(QString::fromStdString(fbx));
    EXPECT_TRUE(button->isEnabled());
    auto* preset = dialog->findChild<QComboBox*>("exportPreset");
    preset->setCurrentIndex(preset->findData("unreal"));
    dialog->findChild<QCheckBox*>("exportControllers")->setChecked(true);
    dialog->findChild<QCheckBox*>("exportRom")->setChecked(true);
    dialog->findChild<QSpinBox*>("exportProxyVertices")->setValue(3000);
    const io::ExportRequest request = dialog->request();
    EXPECT_EQ(request.preset, io::ExportPreset::Unreal);
    EXPECT_TRUE(request.controllers && request.rangeOfMotion && !request.currentPose);
    EXPECT_EQ(request.proxyVertices, 3000u);
    EXPECT_TRUE(request.embedTextures) << "textures inside the FBX unless asked";
    auto* beside = dialog->findChild<QCheckBox*>("exportTexturesBeside");
    ASSERT_TRUE(beside);
    beside->setChecked(true);
    EXPECT_FALSE(dialog->request().embedTextures);
    beside->setChecked(false);

    QTest::mouseClick(button, Qt::LeftButton);
    EXPECT_EQ(dialog->findChild<QProgressBar*>("exportProgress")->value(), 1000);
    const QString report = dialog->findChild<QPlainTextEdit*>("exportReport")->toPlainText();
    EXPECT_TRUE(report.endsWith("Exported " + QString::fromStdString(fbx))) << report.toStdString();
    ASSERT_TRUE(std::filesystem::exists(fbx)) << "the rig was built and exported";
    std::ifstream file(fbx, std::ios::binary);
    std::string magic(20, '\0');
    file.read(magic.data(), 20);
    EXPECT_EQ(magic, "Kaydara FBX Binary  ") << "binary FBX, never ASCII";
    dialog->grab().save(QString::fromStdString(test::outputPath("export-dialog.png")));

    // A name map that does not exist: the report says so and nothing is written.
    const std::string glb = test::outputPath("dialog-missing-map.glb");
    std::filesystem::remove(glb);
    path->setText(QString::fromStdString(glb));
    dialog->findChild<QLineEdit*>("exportNames")->setText("/nonexistent/names.yml");
    QTest::mouseClick(button, Qt::LeftButton);
    EXPECT_TRUE(dialog->findChild<QPlainTextEdit*>("exportReport")->toPlainText().contains("/nonexistent/names.yml"));
    EXPECT_FALSE(std::filesystem::exists(glb));
}

TEST(ExportDialog, TheUnityPresetRefusesTheQuadrupedListingTheBonesUntilForced)
{
    test::Editor editor;
    auto& w = editor.window;
    ASSERT_TRUE(w.openFile(RIGSMITH_SOURCE_DIR "/resources/samples/quadruped.yml"));
    w.action("exportRig")->trigger();
    widgets::ExportDialog* dialog = w.exportDialog();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(dialog));
    const std::string glb = test::outputPath("dialog-unity-quadruped.glb");
    std::filesystem::remove(glb);
    dialog->findChild<QLineEdit*>("exportPath")->setText(QString::fromStdString(glb));
    auto* preset = dialog->findChild<QComboBox*>("exportPreset");
    preset->setCurrentIndex(preset->findData("unity"));
    dialog->findChild<QCheckBox*>("exportRom")->setChecked(true);
    dialog->findChild<QSpinBox*>("exportFps")->setValue(24);
    dialog->findChild<QCheckBox*>("exportClipPerControl")->setChecked(true);
    EXPECT_EQ(dialog->request().framesPerSecond, 24.0);
    EXPECT_TRUE(dialog->request().clipPerControl);
    auto* button = dialog->findChild<QPushButton*>("exportButton");
    auto* report = dialog->findChild<QPlainTextEdit*>("exportReport");

    QTest::mouseClick(button, Qt::LeftButton);
    EXPECT_TRUE(report->toPlainText().contains("LeftUpperArm (no left arm.limb instance)")) << report->toPlainText().toStdString();
    EXPECT_TRUE(report->toPlainText().contains("Not exported")) << report->toPlainText().toStdString();
    EXPECT_FALSE(std::filesystem::exists(glb));

    dialog->findChild<QCheckBox*>("exportForce")->setChecked(true);
    QTest::mouseClick(button, Qt::LeftButton);
    EXPECT_TRUE(report->toPlainText().endsWith("Exported " + QString::fromStdString(glb))) << report->toPlainText().toStdString();
    EXPECT_TRUE(std::filesystem::exists(glb));
}

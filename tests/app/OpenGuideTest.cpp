// Opening a guide in the editor (issue 18 item 13): what the Build log says.
#include "EditorTestSupport.h"

#include "LogPanel.h"
#include "io/GuideFile.h"

#include <QTest>

#include <gtest/gtest.h>

#include <fstream>

using namespace rs;
using namespace rs::test;

TEST(Editor, OpeningAGuideWithAMissingTemplateWarnsInTheBuildLogAboutTheInstance)
{
    Editor e;
    app::MainWindow& w = e.window;
    std::string text = io::writeGuideText(w.session().document());
    const std::string used = "template: neck.head";
    ASSERT_NE(text.find(used), std::string::npos);
    text.replace(text.find(used), used.size(), "template: neck.gone");
    const std::string path = outputPath("missing-template.yml");
    std::ofstream(path) << text;

    ASSERT_TRUE(w.openFile(QString::fromStdString(path)));
    widgets::LogPanel* log = w.log();
    QListWidgetItem* warning = nullptr;
    for (int row = log->count() - 1; row >= 0 && !warning; --row)
        if (log->item(row)->text().contains("unknown template 'neck.gone'"))
            warning = log->item(row);
    ASSERT_NE(warning, nullptr) << "opening says at once that the template is missing";
    EXPECT_TRUE(warning->text().startsWith(QString::fromStdString(path) + ": warning: instance 'neck'"))
        << warning->text().toStdString();

    w.session().select({});
    log->scrollToItem(warning);
    QTest::mouseClick(log->viewport(), Qt::LeftButton, {}, log->visualItemRect(warning).center());
    EXPECT_EQ(w.session().selection().instance, w.session().document().instanceNamed("neck")->id)
        << "the message's subject is the instance";
}

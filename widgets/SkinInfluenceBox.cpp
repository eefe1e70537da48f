#include "SkinInfluenceBox.h"

#include <QComboBox>
#include <QFileDialog>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>
#include <QVBoxLayout>

namespace rs::widgets {

namespace {

QString meshList(const std::vector<std::string>& meshes)
{
    QStringList quoted;
    for (const std::string& m : meshes)
        quoted.push_back("'" + QString::fromStdString(m) + "'");
    return quoted.join(", ");
}

} // namespace

SkinInfluenceBox::SkinInfluenceBox(QWidget* parent) : QGroupBox(tr("Influences"), parent)
{
    setObjectName("skinInfluenceBox");
    auto* column = new QVBoxLayout(this);
    auto* form = new QFormLayout;
    m_missing = new QComboBox(this);
    m_missing->setObjectName("missingInfluences");
    // In skin::MissingInfluences order: Stop, Map, Create.
    m_missing->addItems({tr("Stop and list them"), tr("Map them by the name map"), tr("Create them as joints under their matched parent")});
    m_missing->setToolTip(tr("An influence of the chunks that is no skin joint of the rig (by identity or name): stop the import "
                             "and list them, map them with a name map, or add each as a joint of the guide (named as the influence, at its bind position) under the joint its nearest matched ancestor is; one undo step with the weights"));
    form->addRow(tr("Missing influences"), m_missing);
    auto* mapRow = new QHBoxLayout;
    m_nameMap = new QLineEdit(this);
    m_nameMap->setObjectName("nameMapFile");
    m_nameMap->setPlaceholderText(tr("none"));
    m_nameMap->setToolTip(tr("A name map file: one 'old_influence=rig_joint' (or 'old: new') per line, # comments. "
                             "Applied whenever it is given; needed to map"));
    auto* browse = new QPushButton(tr("..."), this);
    browse->setObjectName("chooseNameMap");
    browse->setToolTip(tr("Choose a name map file"));
    connect(browse, &QPushButton::clicked, this, [this] {
        const QString path = QFileDialog::getOpenFileName(this, tr("Influence name map"), {}, tr("Name maps (*.txt *.map *.yml *.yaml);;All files (*)"));
        if (!path.isEmpty())
            setNameMapFile(path);
    });
    mapRow->addWidget(m_nameMap, 1);
    mapRow->addWidget(browse);
    form->addRow(tr("Name map"), mapRow);
    column->addLayout(form);
    m_heading = new QLabel(this);
    m_heading->setObjectName("influenceResultHeading");
    m_heading->setWordWrap(true);
    m_results = new QListWidget(this);
    m_results->setObjectName("influenceResults");
    m_results->setMaximumHeight(90);
    column->addWidget(m_heading);
    column->addWidget(m_results);
    connect(m_missing, &QComboBox::currentIndexChanged, this, &SkinInfluenceBox::updateEnabled);
    clearResults();
    updateEnabled();
}

skin::MissingInfluences SkinInfluenceBox::missing() const { return skin::MissingInfluences(m_missing->currentIndex()); }
void SkinInfluenceBox::setMissing(skin::MissingInfluences rule) { m_missing->setCurrentIndex(int(rule)); }
QString SkinInfluenceBox::nameMapFile() const { return m_nameMap->text().trimmed(); }
void SkinInfluenceBox::setNameMapFile(const QString& path) { m_nameMap->setText(path); }

void SkinInfluenceBox::updateEnabled()
{
    // Mapping without a map cannot work: say so where the map goes.
    const bool needed = missing() == skin::MissingInfluences::Map;
    m_nameMap->setPlaceholderText(needed ? tr("required to map") : tr("none"));
}

void SkinInfluenceBox::clearResults()
{
    m_results->clear();
    m_results->hide();
    m_heading->clear();
    m_heading->hide();
}

void SkinInfluenceBox::showMissing(const std::vector<skin::InfluenceMatch>& missing)
{
    clearResults();
    if (missing.empty())
        return;
    m_heading->setText(tr("The import stopped: %n influence(s) of the chunks are no skin joint of the rig. "
                          "Map them with a name map, or choose Create.", nullptr, int(missing.size())));
    for (const skin::InfluenceMatch& m : missing)
        m_results->addItem(tr("%1  (weights %2)").arg(QString::fromStdString(m.name), meshList(m.meshes)));
    m_heading->show();
    m_results->show();
}

void SkinInfluenceBox::showMoved(const std::vector<skin::InfluenceMatch>& matches)
{
    using How = skin::InfluenceMatch::How;
    clearResults();
    int mapped = 0, created = 0;
    for (const skin::InfluenceMatch& m : matches) {
        if (m.how != How::Mapped && m.how != How::Created)
            continue;
        (m.how == How::Mapped ? mapped : created) += 1;
        m_results->addItem(tr("%1 -> %2  (%3; weights %4)")
                               .arg(QString::fromStdString(m.name), QString::fromStdString(m.target),
                                    m.how == How::Mapped ? tr("mapped") : tr("created"), meshList(m.meshes)));
    }
    if (mapped + created == 0)
        return;
    m_heading->setText(tr("%1 influences mapped by name, %2 created as joints").arg(mapped).arg(created));
    m_heading->show();
    m_results->show();
}

} // namespace rs::widgets

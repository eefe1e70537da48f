#include "ExportDialog.h"

#include "io/RigExport.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QFileDialog>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QSpinBox>
#include <QVBoxLayout>

namespace rs::widgets {

namespace {

QCheckBox* checkBox(QWidget* parent, const char* objectName, const QString& text, const QString& tip)
{
    auto* box = new QCheckBox(text, parent);
    box->setObjectName(objectName);
    box->setToolTip(tip);
    return box;
}

QWidget* withBrowse(QWidget* parent, QLineEdit* edit, QPushButton*& button)
{
    auto* row = new QWidget(parent);
    auto* layout = new QHBoxLayout(row);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(edit, 1);
    button = new QPushButton(QObject::tr("Browse..."), row);
    layout->addWidget(button);
    return row;
}

} // namespace

ExportDialog::ExportDialog(QWidget* parent) : QDialog(parent)
{
    setObjectName("exportDialog");
    setWindowTitle(tr("Export Rig"));
    auto* form = new QFormLayout;

    m_path = new QLineEdit(this);
    m_path->setObjectName("exportPath");
    m_path->setPlaceholderText(tr("rig.glb, rig.gltf or rig.fbx"));
    QPushButton* browsePath = nullptr;
    form->addRow(tr("File"), withBrowse(this, m_path, browsePath));

    m_preset = new QComboBox(this);
    m_preset->setObjectName("exportPreset");
    m_preset->addItem(tr("glTF (Y-up, metres)"), "gltf");
    m_preset->addItem(tr("Unreal (Z-up, centimetres, root joint)"), "unreal");
    m_preset->addItem(tr("Unity (Y-up, metres, humanoid names)"), "unity");
    m_preset->setToolTip(tr("Unreal's axes and units apply to FBX; glTF is always Y-up metres"));
    form->addRow(tr("Preset"), m_preset);

    m_names = new QLineEdit(this);
    m_names->setObjectName("exportNames");
    m_names->setPlaceholderText(tr("the preset's (Unity: humanoid names)"));
    m_names->setToolTip(tr("A YAML name map (rigsmith_names: 1, names: {node id or name: export name}), or 'unity'"));
    QPushButton* browseNames = nullptr;
    form->addRow(tr("Name map"), withBrowse(this, m_names, browseNames));

    m_controllers = checkBox(this, "exportControllers", tr("Include controllers"),
                             tr("Controllers as non-joint nodes tagged in extras ({\"rig\": {\"kind\": \"controller\"}})"));
    m_rangeOfMotion = checkBox(this, "exportRom", tr("Range-of-motion clip"),
                               tr("An animation exercising each controller in turn from the test pose (FK in FK, IK goals "
                                  "within reach, nothing stretched), for checking deformations in the engine"));
    m_currentPose = checkBox(this, "exportCurrentPose", tr("Include the current pose"),
                             tr("The pose on the nodes; the bind pose stays in the inverse bind matrices"));
    m_fixNames = checkBox(this, "exportFixNames", tr("Fix names"), tr("Apply the validator's safe renames"));
    m_fixWeights = checkBox(this, "exportFixWeights", tr("Fix weights"),
                            tr("Keep the 4 largest influences per vertex and normalise"));
    m_force = checkBox(this, "exportForce", tr("Export despite errors"),
                       tr("Write the file even when the validator finds errors (they are reported as warnings)"));
    for (QCheckBox* box : {m_controllers, m_rangeOfMotion, m_currentPose, m_fixNames, m_fixWeights, m_force})
        form->addRow(QString(), box);

    m_proxyVertices = new QSpinBox(this);
    m_proxyVertices->setObjectName("exportProxyVertices");
    m_proxyVertices->setRange(0, 2000000);
    m_proxyVertices->setSingleStep(1000);
    m_proxyVertices->setSpecialValueText(tr("none"));
    m_proxyVertices->setSuffix(tr(" vertices"));
    m_proxyVertices->setToolTip(tr("Bind a generated test mesh (tubes along the bones) to check skinning in the engine"));
    form->addRow(tr("Test mesh"), m_proxyVertices);

    m_framesPerSecond = new QSpinBox(this);
    m_framesPerSecond->setObjectName("exportFps");
    m_framesPerSecond->setRange(1, 1000);
    m_framesPerSecond->setValue(30);
    m_framesPerSecond->setSuffix(tr(" fps"));
    m_framesPerSecond->setToolTip(tr("The range of motion's keys sit on whole frames at this rate"));
    m_clipPerControl = checkBox(this, "exportClipPerControl", tr("One clip per controller"),
                                tr("The range of motion as one clip per controller instead of clips of a minute at "
                                   "most with a marker per controller"));
    form->addRow(tr("Range of motion"), m_framesPerSecond);
    form->addRow(QString(), m_clipPerControl);
    m_texturesBeside = checkBox(this, "exportTexturesBeside", tr("Textures beside the FBX"),
                                tr("Copy each texture beside the FBX and name it relatively instead of embedding it"));
    form->addRow(tr("Textures"), m_texturesBeside);

    m_progress = new QProgressBar(this);
    m_progress->setObjectName("exportProgress");
    m_progress->setRange(0, 1000);
    m_progress->setValue(0);
    m_progress->setTextVisible(false);
    m_report = new QPlainTextEdit(this);
    m_report->setObjectName("exportReport");
    m_report->setReadOnly(true);
    m_report->setPlaceholderText(tr("The validator's report appears here"));

    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    m_export = buttons->addButton(tr("Export"), QDialogButtonBox::ActionRole);
    m_export->setObjectName("exportButton");
    m_export->setDefault(true);

    auto* layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(m_progress);
    layout->addWidget(m_report, 1);
    layout->addWidget(buttons);
    resize(560, 620);

    connect(browsePath, &QPushButton::clicked, this, &ExportDialog::browse);
    connect(browseNames, &QPushButton::clicked, this, &ExportDialog::browseNames);
    connect(m_path, &QLineEdit::textChanged, this, &ExportDialog::updateButtons);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(m_export, &QPushButton::clicked, this, [this] {
        m_report->clear();
        setProgress(0.0);
        emit exportRequested(request());
    });
    updateButtons();
}

io::ExportRequest ExportDialog::request() const
{
    io::ExportRequest r;
    r.path = m_path->text().trimmed().toStdString();
    r.preset = io::presetNamed(m_preset->currentData().toString().toStdString()).value_or(io::ExportPreset::Gltf);
    r.names = m_names->text().trimmed().toStdString();
    r.controllers = m_controllers->isChecked();
    r.rangeOfMotion = m_rangeOfMotion->isChecked();
    r.currentPose = m_currentPose->isChecked();
    r.fixNames = m_fixNames->isChecked();
    r.fixWeights = m_fixWeights->isChecked();
    r.force = m_force->isChecked();
    r.proxyVertices = std::size_t(m_proxyVertices->value());
    r.framesPerSecond = double(m_framesPerSecond->value());
    r.clipPerControl = m_clipPerControl->isChecked();
    r.embedTextures = !m_texturesBeside->isChecked();
    return r;
}

void ExportDialog::setPath(const QString& path) { m_path->setText(path); }

void ExportDialog::setProgress(double fraction) { m_progress->setValue(int(fraction * 1000.0 + 0.5)); }

void ExportDialog::showReport(const Diagnostics& report)
{
    QStringList lines;
    for (const auto& d : report)
        lines << QString::fromStdString(d.format());
    if (!hasErrors(report))
        lines << tr("Exported %1").arg(m_path->text());
    else if (!m_force->isChecked())
        lines << tr("Not exported. \"Export despite errors\" writes it anyway, with these errors as warnings.");
    m_report->setPlainText(lines.join('\n'));
}

void ExportDialog::browse()
{
    const QString path = QFileDialog::getSaveFileName(this, tr("Export rig"), m_path->text(),
                                                      tr("glTF binary (*.glb);;glTF (*.gltf);;FBX binary (*.fbx)"));
    if (!path.isEmpty())
        m_path->setText(path);
}

void ExportDialog::browseNames()
{
    const QString path = QFileDialog::getOpenFileName(this, tr("Name map"), m_names->text(), tr("Name maps (*.yml *.yaml)"));
    if (!path.isEmpty())
        m_names->setText(path);
}

void ExportDialog::updateButtons()
{
    const bool known = io::exportFormatOf(m_path->text().trimmed().toStdString()).has_value();
    m_export->setEnabled(known);
    m_export->setToolTip(known ? QString() : tr("Name the file .glb, .gltf or .fbx"));
}

} // namespace rs::widgets

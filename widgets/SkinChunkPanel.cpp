#include "SkinChunkPanel.h"

#include "SkinInfluenceBox.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QListWidget>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QTabWidget>
#include <QTreeWidget>
#include <QVBoxLayout>

namespace rs::widgets {

namespace {

QDoubleSpinBox* number(QWidget* parent, double low, double high, double step, int decimals, const QString& tip)
{
    auto* box = new QDoubleSpinBox(parent);
    box->setRange(low, high);
    box->setSingleStep(step);
    box->setDecimals(decimals);
    box->setToolTip(tip);
    return box;
}

QSpinBox* count(QWidget* parent, int low, int high, const QString& tip)
{
    auto* box = new QSpinBox(parent);
    box->setRange(low, high);
    box->setToolTip(tip);
    return box;
}

} // namespace

SkinChunkPanel::SkinChunkPanel(QWidget* parent) : QWidget(parent)
{
    auto* tabs = new QTabWidget(this);
    tabs->setObjectName("skinChunkTabs");
    auto* transfer = new QWidget(tabs);
    auto* column = new QVBoxLayout(transfer);
    column->addWidget(makeExportBox());
    column->addWidget(makeImportBox(), 1);
    tabs->addTab(transfer, tr("Export / Import"));
    tabs->addTab(makeOptionsBox(), tr("Options"));
    tabs->addTab(makeInspectorBox(), tr("Inspector"));
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(2, 2, 2, 2);
    layout->addWidget(tabs);
    setOptions({});
    updateEnabled();
}

QAbstractButton* SkinChunkPanel::addButton(QWidget* parent, const QString& name, const QString& text, const QString& tip)
{
    auto* b = new QPushButton(text, parent);
    b->setObjectName(name);
    b->setToolTip(tip);
    return b;
}

QAbstractButton* SkinChunkPanel::button(const QString& name) const { return findChild<QAbstractButton*>(name); }

QWidget* SkinChunkPanel::makeExportBox()
{
    auto* box = new QGroupBox(tr("Export"), this);
    auto* row = new QHBoxLayout(box);
    m_exportScope = new QComboBox(box);
    m_exportScope->addItems({tr("Whole character"), tr("Meshes with selected vertices"), tr("Selected vertices"), tr("Selected joints' vertices")});
    m_exportScope->setToolTip(tr("What the chunk file holds: every bound mesh, the whole meshes you selected vertices on, only the selected "
                                 "vertices, or the vertices the selected joints (or the selected template instance's skin joints) weight, "
                                 "with all their weights"));
    row->addWidget(m_exportScope, 1);
    QAbstractButton* save = addButton(box, "export", tr("Export..."), tr("Write the weights, positions (current pose and bind pose) and influences to a .rschunks file"));
    connect(save, &QAbstractButton::clicked, this, &SkinChunkPanel::exportRequested);
    row->addWidget(save);
    return box;
}

QWidget* SkinChunkPanel::makeImportBox()
{
    auto* box = new QGroupBox(tr("Import"), this);
    auto* column = new QVBoxLayout(box);
    m_files = new QListWidget(box);
    m_files->setObjectName("chunkFiles");
    m_files->setSelectionMode(QAbstractItemView::ExtendedSelection);
    m_files->setMaximumHeight(80);
    m_files->setToolTip(tr("Chunk files to import, merged: the most recently exported chunk wins a mesh name clash"));
    column->addWidget(m_files);
    auto* fileRow = new QHBoxLayout;
    QAbstractButton* add = addButton(box, "addFiles", tr("Add Files..."), tr("Choose .rschunks files to import"));
    QAbstractButton* remove = addButton(box, "removeFiles", tr("Remove"), tr("Remove the selected files from the list"));
    connect(add, &QAbstractButton::clicked, this, [this] {
        const QStringList chosen = QFileDialog::getOpenFileNames(this, tr("Import skin chunks"), {}, tr("Skin chunks (*.rschunks);;All files (*)"));
        setImportFiles(importFiles() + chosen);
    });
    connect(remove, &QAbstractButton::clicked, this, [this] {
        qDeleteAll(m_files->selectedItems());
        updateEnabled();
        emit filesChanged();
    });
    fileRow->addWidget(add);
    fileRow->addWidget(remove);
    fileRow->addStretch(1);
    column->addLayout(fileRow);

    auto* form = new QFormLayout;
    m_onto = new QComboBox(box);
    m_onto->addItems({tr("Every mesh"), tr("Selected vertices")});
    form->addRow(tr("Onto"), m_onto);
    m_append = new QCheckBox(tr("Append: keep the weights the chunks do not cover"), box);
    m_append->setObjectName("appendImport");
    m_append->setToolTip(tr("A mesh loaded 1:1 from a chunk of only some of its vertices keeps its own weights on the others; "
                            "off, the import replaces every vertex's weights (the others by the fallback method)"));
    form->addRow(m_append);
    m_previewSelects = new QComboBox(box);
    m_previewSelects->addItems({tr("Vertices transferred (not 1:1)"), tr("Vertices loaded 1:1")});
    m_previewSelects->setToolTip(tr("Preview runs the decision tree without applying it and selects these vertices in the viewport"));
    form->addRow(tr("Preview selects"), m_previewSelects);
    column->addLayout(form);
    m_influences = new SkinInfluenceBox(box);
    column->addWidget(m_influences);
    auto* runRow = new QHBoxLayout;
    QAbstractButton* preview = addButton(box, "preview", tr("Preview"), tr("Run the import without applying it: the table shows each mesh's route and counts"));
    QAbstractButton* apply = addButton(box, "import", tr("Import"), tr("Import the weights as one undo step (Cancel in the progress dialog changes nothing)"));
    connect(preview, &QAbstractButton::clicked, this, [this] { emit importRequested(true); });
    connect(apply, &QAbstractButton::clicked, this, [this] { emit importRequested(false); });
    runRow->addStretch(1);
    runRow->addWidget(preview);
    runRow->addWidget(apply);
    column->addLayout(runRow);

    m_reports = new QTreeWidget(box);
    m_reports->setObjectName("chunkReports");
    m_reports->setHeaderLabels({tr("Mesh"), tr("Route"), tr("Source"), tr("Vertices"), tr("1:1"), tr("Transferred"), tr("Inpainted"),
                                tr("Normal filter fallback"), tr("ms")});
    m_reports->setRootIsDecorated(false);
    m_reports->header()->setSectionResizeMode(QHeaderView::ResizeToContents);
    column->addWidget(m_reports, 1);
    auto* routeRow = new QHBoxLayout;
    m_routeColours = new QCheckBox(tr("Colour vertices by step"), box);
    m_routeColours->setObjectName("routeColours");
    m_routeColours->setToolTip(tr("Colour each vertex of the character by the step that placed its weights: the last import, "
                                  "preview or re-fit (View > Display > Skin Chunk Steps)"));
    connect(m_routeColours, &QCheckBox::toggled, this, &SkinChunkPanel::routeColoursToggled);
    m_routeLegend = new QLabel(box);
    m_routeLegend->setObjectName("routeLegend");
    m_routeLegend->setTextFormat(Qt::RichText);
    routeRow->addWidget(m_routeColours);
    routeRow->addWidget(m_routeLegend, 1);
    column->addLayout(routeRow);
    return box;
}

void SkinChunkPanel::setRouteColours(bool on)
{
    const QSignalBlocker quiet(m_routeColours); // set from the View menu's action: no echo
    m_routeColours->setChecked(on);
}

void SkinChunkPanel::setRouteLegend(const QList<QPair<QColor, QString>>& entries)
{
    QString html;
    for (const auto& [colour, text] : entries)
        html += QString("<span style=\"color:%1\">&#9632;</span>&nbsp;%2&nbsp;&nbsp; ").arg(colour.name(), text.toHtmlEscaped());
    m_routeLegend->setText(html);
}

QWidget* SkinChunkPanel::makeOptionsBox()
{
    auto* page = new QWidget(this);
    auto* form = new QFormLayout(page);
    m_method = new QComboBox(page);
    m_method->addItems({tr("Closest point"), tr("Closest neighbours"), tr("Weight inpainting")});
    m_method->setToolTip(tr("How a mesh whose vertex count or order changed gets its weights"));
    form->addRow(tr("Fallback method"), m_method);
    m_search = new QCheckBox(tr("Search all chunks by vertex count and order"), page);
    form->addRow(m_search);
    m_uber = new QCheckBox(tr("Always use the uber chunk (all chunks as one point cloud)"), page);
    form->addRow(m_uber);
    m_sourcePose = new QComboBox(page);
    m_sourcePose->addItems({tr("Pre-deformed (bind pose)"), tr("Pose at export")});
    form->addRow(tr("Source points"), m_sourcePose);
    m_neighbours = count(page, 1, 32, tr("Closest neighbours: how many source vertices blend"));
    form->addRow(tr("Neighbours"), m_neighbours);
    m_multiplier = number(page, 1.0, 1000.0, 0.5, 2, tr("Closest neighbours: within the nearest distance times this"));
    form->addRow(tr("Distance multiplier"), m_multiplier);
    m_normalFilter = new QCheckBox(tr("Vertex normal filter"), page);
    m_tolerance = number(page, -1.0, 1.0, 0.05, 2, tr("The least dot product of source and target normals (0.75: within about 41 degrees)"));
    form->addRow(m_normalFilter, m_tolerance);
    m_smoothSteps = count(page, 0, 100, tr("Smoothing steps on a denser target (0: none)"));
    form->addRow(tr("Smoothing steps"), m_smoothSteps);
    m_smoothThreshold = number(page, 0.0, 1.0, 0.05, 2, tr("Smooth only where a neighbour's weight differs by more than this"));
    form->addRow(tr("Smoothing threshold"), m_smoothThreshold);
    m_maxInfluences = count(page, 0, 16, tr("Influences kept per vertex (0: the most any source vertex has)"));
    form->addRow(tr("Max influences"), m_maxInfluences);
    m_inpaintDistance = number(page, 0.0, 1000.0, 0.01, 3, tr("Inpainting: metres a copied closest point may be away (0: 5% of the mesh's size)"));
    form->addRow(tr("Inpaint distance (m)"), m_inpaintDistance);
    m_inpaintAngle = number(page, 0.0, 180.0, 5.0, 1, tr("Inpainting: how far the closest point's normal may turn, in degrees"));
    form->addRow(tr("Inpaint angle (°)"), m_inpaintAngle);
    connect(m_method, &QComboBox::currentIndexChanged, this, &SkinChunkPanel::updateEnabled);
    connect(m_normalFilter, &QCheckBox::toggled, this, &SkinChunkPanel::updateEnabled);
    return page;
}

QWidget* SkinChunkPanel::makeInspectorBox()
{
    auto* page = new QWidget(this);
    auto* column = new QVBoxLayout(page);
    auto* row = new QHBoxLayout;
    m_from = count(page, 0, 1 << 30, tr("The first influence and vertex row shown"));
    m_from->setObjectName("inspectFrom");
    m_limit = count(page, 0, 100000, tr("How many rows of each are shown"));
    m_limit->setObjectName("inspectLimit");
    m_limit->setValue(10);
    for (QSpinBox* box : {m_from, m_limit})
        connect(box, &QSpinBox::valueChanged, this, [this] {
            if (!m_inspected.isEmpty())
                emit inspectRequested(m_inspected); // the same file, other rows
        });
    row->addWidget(new QLabel(tr("From"), page));
    row->addWidget(m_from);
    row->addWidget(new QLabel(tr("Limit"), page));
    row->addWidget(m_limit);
    QAbstractButton* inspect = addButton(page, "inspect", tr("Inspect..."), tr("Show what a chunk file holds (the selected import file, or choose one)"));
    connect(inspect, &QAbstractButton::clicked, this, [this] {
        QString file = m_files->currentItem() ? m_files->currentItem()->text() : QString();
        if (file.isEmpty())
            file = QFileDialog::getOpenFileName(this, tr("Inspect skin chunks"), {}, tr("Skin chunks (*.rschunks);;All files (*)"));
        if (!file.isEmpty())
            emit inspectRequested(file);
    });
    row->addStretch(1);
    row->addWidget(inspect);
    column->addLayout(row);
    m_inspector = new QPlainTextEdit(page);
    m_inspector->setObjectName("chunkInspector");
    m_inspector->setReadOnly(true);
    m_inspector->setLineWrapMode(QPlainTextEdit::NoWrap);
    m_inspector->setFont(QFont("monospace"));
    column->addWidget(m_inspector, 1);
    return page;
}

void SkinChunkPanel::updateEnabled()
{
    const int method = m_method->currentIndex();
    m_neighbours->setEnabled(method == 1);
    m_multiplier->setEnabled(method == 1);
    m_normalFilter->setEnabled(method != 2); // inpainting has its own normal test
    m_tolerance->setEnabled(method != 2 && m_normalFilter->isChecked());
    m_inpaintDistance->setEnabled(method == 2);
    m_inpaintAngle->setEnabled(method == 2);
    const bool files = m_files->count() > 0;
    for (const char* name : {"preview", "import"})
        if (QAbstractButton* b = button(name))
            b->setEnabled(files);
}

SkinChunkPanel::ExportScope SkinChunkPanel::exportScope() const { return ExportScope(m_exportScope->currentIndex()); }
void SkinChunkPanel::setExportScope(ExportScope scope) { m_exportScope->setCurrentIndex(int(scope)); }
bool SkinChunkPanel::importOntoSelection() const { return m_onto->currentIndex() == 1; }
void SkinChunkPanel::setImportOntoSelection(bool on) { m_onto->setCurrentIndex(on ? 1 : 0); }
bool SkinChunkPanel::appendImport() const { return m_append->isChecked(); }
void SkinChunkPanel::setAppendImport(bool on) { m_append->setChecked(on); }
SkinChunkPanel::PreviewSelects SkinChunkPanel::previewSelects() const { return PreviewSelects(m_previewSelects->currentIndex()); }
void SkinChunkPanel::setPreviewSelects(PreviewSelects what) { m_previewSelects->setCurrentIndex(int(what)); }
int SkinChunkPanel::inspectFrom() const { return m_from->value(); }
int SkinChunkPanel::inspectLimit() const { return m_limit->value(); }

QStringList SkinChunkPanel::importFiles() const
{
    QStringList out;
    for (int i = 0; i < m_files->count(); ++i)
        out.push_back(m_files->item(i)->text());
    return out;
}

void SkinChunkPanel::setImportFiles(const QStringList& files)
{
    m_files->clear();
    QStringList unique = files;
    unique.removeDuplicates();
    m_files->addItems(unique);
    if (m_files->count() > 0)
        m_files->setCurrentRow(m_files->count() - 1);
    updateEnabled();
    emit filesChanged();
}

skin::TransferOptions SkinChunkPanel::options() const
{
    skin::TransferOptions o;
    o.method = skin::TransferMethod(m_method->currentIndex());
    o.searchByCountAndOrder = m_search->isChecked();
    o.forceUberChunk = m_uber->isChecked();
    o.usePreDeformed = m_sourcePose->currentIndex() == 0;
    o.neighbourCount = m_neighbours->value();
    o.neighbourDistanceMultiplier = m_multiplier->value();
    o.normalFilter = m_normalFilter->isChecked();
    o.normalTolerance = m_tolerance->value();
    o.smoothSteps = m_smoothSteps->value();
    o.weightDifferenceThreshold = m_smoothThreshold->value();
    o.maxInfluences = m_maxInfluences->value();
    o.inpaintDistance = m_inpaintDistance->value();
    o.inpaintAngleDegrees = m_inpaintAngle->value();
    return o;
}

void SkinChunkPanel::setOptions(const skin::TransferOptions& o)
{
    m_method->setCurrentIndex(int(o.method));
    m_search->setChecked(o.searchByCountAndOrder);
    m_uber->setChecked(o.forceUberChunk);
    m_sourcePose->setCurrentIndex(o.usePreDeformed ? 0 : 1);
    m_neighbours->setValue(o.neighbourCount);
    m_multiplier->setValue(o.neighbourDistanceMultiplier);
    m_normalFilter->setChecked(o.normalFilter);
    m_tolerance->setValue(o.normalTolerance);
    m_smoothSteps->setValue(o.smoothSteps);
    m_smoothThreshold->setValue(o.weightDifferenceThreshold);
    m_maxInfluences->setValue(o.maxInfluences);
    m_inpaintDistance->setValue(o.inpaintDistance);
    m_inpaintAngle->setValue(o.inpaintAngleDegrees);
    updateEnabled();
}

void SkinChunkPanel::showReports(const std::vector<skin::MeshImportReport>& reports, bool preview)
{
    m_reports->clear();
    for (const skin::MeshImportReport& r : reports) {
        const QString route = QString::fromLatin1(skin::importRouteName(r.route)) + (preview ? tr(" (preview)") : QString());
        auto* item = new QTreeWidgetItem(m_reports, {QString::fromStdString(r.mesh), route, QString::fromStdString(r.source),
                                                     QString::number(r.vertices), QString::number(r.oneToOne),
                                                     QString::number(r.closestPoint + r.closestNeighbours + r.singleInfluence),
                                                     QString::number(r.inpainted), QString::number(r.normalFilterFallbacks),
                                                     QString::number(int(r.milliseconds))});
        item->setToolTip(0, QString::fromStdString(r.why));
        item->setToolTip(1, QString::fromStdString(r.why));
    }
}

void SkinChunkPanel::showInspection(const QString& text, const QString& file)
{
    m_inspected = file;
    m_inspector->setPlainText(text);
}

} // namespace rs::widgets

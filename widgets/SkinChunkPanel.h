#pragma once
// The Skin Chunks dock (issue 20 item 6): export the character's weights as a
// skin chunk file (the whole character, the meshes with selected vertices,
// only the selected vertices, or the vertices the selected joints weight);
// import one or many chunk files with every option of skin::TransferOptions
// and the missing-influence choices (SkinInfluenceBox) onto everything or the
// selected vertices, replacing the meshes' weights or appending,
// or preview the import (the decision tree run without applying: per mesh its
// route and counts, and the vertices of one route selected); and inspect a
// chunk file (its meshes, counts, influences, dates, user and vertex rows
// from an index, at most a limit; changing either shows the file again). It
// only holds options and shows results;
// the app runs each request as session work (an import is one undo step).
#include "skin/Transfer.h"

#include <QColor>
#include <QList>
#include <QPair>
#include <QString>
#include <QStringList>
#include <QWidget>

#include <vector>

class QAbstractButton;
class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QListWidget;
class QPlainTextEdit;
class QSpinBox;
class QTreeWidget;

namespace rs::widgets {

class SkinInfluenceBox;

class SkinChunkPanel : public QWidget {
    Q_OBJECT
public:
    // What an export covers, in session::SkinScope terms.
    enum class ExportScope { Character, SelectedMeshes, SelectedVertices, SelectedJoints };
    // Which vertices a preview selects.
    enum class PreviewSelects { Transferred, OneToOne };

    explicit SkinChunkPanel(QWidget* parent = nullptr);

    ExportScope exportScope() const;
    void setExportScope(ExportScope scope);
    QStringList importFiles() const;
    void setImportFiles(const QStringList& files);
    skin::TransferOptions options() const; // without progress
    void setOptions(const skin::TransferOptions& options);
    bool importOntoSelection() const;
    void setImportOntoSelection(bool on);
    // Append: a mesh loaded 1:1 from a chunk of some of its vertices keeps its
    // weights on the others (session::SkinImportJob::append); off: replaced.
    bool appendImport() const;
    void setAppendImport(bool on);
    PreviewSelects previewSelects() const;
    void setPreviewSelects(PreviewSelects what);

    // One row per mesh: route, source, counts per method; `preview`: nothing was applied.
    void showReports(const std::vector<skin::MeshImportReport>& reports, bool preview);
    // `file`: what the text describes; From and Limit changes ask for it again.
    void showInspection(const QString& text, const QString& file = {});
    int inspectFrom() const;
    int inspectLimit() const;
    QSpinBox* inspectFromBox() const { return m_from; }
    QSpinBox* inspectLimitBox() const { return m_limit; }

    // Missing influences (stop / map / create) and the name map file, and what they did.
    SkinInfluenceBox* influences() const { return m_influences; }
    QTreeWidget* reportList() const { return m_reports; }
    QPlainTextEdit* inspector() const { return m_inspector; }
    // Colour the character's vertices by the step that placed their weights
    // (1:1, transferred, inpainted...), in the viewport outside paint mode;
    // the legend: one entry per step, its colour and what it means.
    QCheckBox* routeColours() const { return m_routeColours; }
    void setRouteColours(bool on);
    void setRouteLegend(const QList<QPair<QColor, QString>>& entries);
    QLabel* routeLegend() const { return m_routeLegend; }
    // Buttons by name (tests): "export", "addFiles", "removeFiles", "preview", "import", "inspect".
    QAbstractButton* button(const QString& name) const;

signals:
    void exportRequested();
    void importRequested(bool preview);
    void inspectRequested(const QString& file); // the current import file, or one chosen
    void filesChanged();
    void routeColoursToggled(bool on);

private:
    QWidget* makeExportBox();
    QWidget* makeImportBox();
    QWidget* makeOptionsBox();
    QWidget* makeInspectorBox();
    QAbstractButton* addButton(QWidget* parent, const QString& name, const QString& text, const QString& tip);
    void updateEnabled();

    QComboBox* m_exportScope = nullptr;
    QListWidget* m_files = nullptr;
    QComboBox* m_method = nullptr;
    QCheckBox* m_search = nullptr;
    QCheckBox* m_uber = nullptr;
    QComboBox* m_sourcePose = nullptr;
    QSpinBox* m_neighbours = nullptr;
    QDoubleSpinBox* m_multiplier = nullptr;
    QCheckBox* m_normalFilter = nullptr;
    QDoubleSpinBox* m_tolerance = nullptr;
    QSpinBox* m_smoothSteps = nullptr;
    QDoubleSpinBox* m_smoothThreshold = nullptr;
    QSpinBox* m_maxInfluences = nullptr;
    QDoubleSpinBox* m_inpaintDistance = nullptr;
    QDoubleSpinBox* m_inpaintAngle = nullptr;
    QComboBox* m_onto = nullptr;
    QCheckBox* m_append = nullptr;
    QComboBox* m_previewSelects = nullptr;
    SkinInfluenceBox* m_influences = nullptr;
    QTreeWidget* m_reports = nullptr;
    QCheckBox* m_routeColours = nullptr;
    QLabel* m_routeLegend = nullptr;
    QSpinBox* m_from = nullptr;
    QSpinBox* m_limit = nullptr;
    QPlainTextEdit* m_inspector = nullptr;
    QString m_inspected; // the file the inspector shows
};

} // namespace rs::widgets

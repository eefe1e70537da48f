#pragma once
// The editor's Export dialog (issue 6): the same choices as
// `rigsmith-cli build GUIDE -o OUT [--preset] [--controllers] [--rom] ...`
// (a path whose extension picks .glb / .gltf / .fbx, the preset, a name map,
// options, the range of motion's frame rate and clips, the validator's fixes
// and force), a progress bar and the report of the last export: a refused
// export (a validator error, a preset that cannot map the rig) lists why and
// says that "Export despite errors" writes it anyway. It does not export by itself: Export emits
// exportRequested(request) and the owner runs it, calling setProgress() and
// showReport().
#include "base/Diagnostic.h"
#include "io/ExportRequest.h"

#include <QDialog>

class QCheckBox;
class QComboBox;
class QLineEdit;
class QPlainTextEdit;
class QProgressBar;
class QPushButton;
class QSpinBox;

namespace rs::widgets {

class ExportDialog : public QDialog {
    Q_OBJECT
public:
    explicit ExportDialog(QWidget* parent = nullptr);

    io::ExportRequest request() const;
    void setPath(const QString& path);
    void setProgress(double fraction);
    void showReport(const Diagnostics& report);

signals:
    void exportRequested(const rs::io::ExportRequest& request);

private:
    void browse();
    void browseNames();
    void updateButtons();

    QLineEdit* m_path = nullptr;
    QComboBox* m_preset = nullptr;
    QLineEdit* m_names = nullptr;
    QCheckBox* m_controllers = nullptr;
    QCheckBox* m_rangeOfMotion = nullptr;
    QCheckBox* m_currentPose = nullptr;
    QCheckBox* m_fixNames = nullptr;
    QCheckBox* m_fixWeights = nullptr;
    QCheckBox* m_force = nullptr;
    QSpinBox* m_proxyVertices = nullptr;
    QSpinBox* m_framesPerSecond = nullptr;
    QCheckBox* m_clipPerControl = nullptr;
    QCheckBox* m_texturesBeside = nullptr;
    QProgressBar* m_progress = nullptr;
    QPlainTextEdit* m_report = nullptr;
    QPushButton* m_export = nullptr;
};

} // namespace rs::widgets

#pragma once
// The Skin Chunks dock's missing-influence choices (issue 20 item 4, as the
// CLI's --missing / --name-map): what an import does with a chunk influence
// the rig has no skin joint of (identity or name) for: stop (default) with the
// list of them, map them by a name map file, or create them as joints of the
// guide under their matched parent ("create"). After a run it lists what stopped the
// import, or which influences were mapped and created. It only holds the
// choices and shows results; the app reads the name map file.
#include "skin/InfluenceMap.h"

#include <QGroupBox>
#include <QString>

#include <vector>

class QComboBox;
class QLabel;
class QLineEdit;
class QListWidget;

namespace rs::widgets {

class SkinInfluenceBox : public QGroupBox {
    Q_OBJECT
public:
    explicit SkinInfluenceBox(QWidget* parent = nullptr);

    skin::MissingInfluences missing() const;
    void setMissing(skin::MissingInfluences rule);
    QString nameMapFile() const; // empty: none
    void setNameMapFile(const QString& path);

    // The influences that stopped an import (skin::missingInfluences), each
    // with the meshes that weight it; empty hides the list.
    void showMissing(const std::vector<skin::InfluenceMatch>& missing);
    // After a run: the influences that were mapped or created (the others landed by identity or name).
    void showMoved(const std::vector<skin::InfluenceMatch>& matches);
    void clearResults();

    QListWidget* resultList() const { return m_results; }
    QLabel* resultHeading() const { return m_heading; }

private:
    void updateEnabled();

    QComboBox* m_missing = nullptr;
    QLineEdit* m_nameMap = nullptr;
    QLabel* m_heading = nullptr;
    QListWidget* m_results = nullptr;
};

} // namespace rs::widgets

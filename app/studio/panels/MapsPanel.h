#pragma once
// The material's maps: one row each (load, clear, bake), and the running bake's progress bar
// with its Cancel button.

#include "jobs/BakeRunner.h"
#include "parallax/material/MapKind.h"

#include <QWidget>
#include <map>

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QProgressBar;
class QPushButton;

namespace px::studio {

class MapRow;
class MaterialDocument;

class MapsPanel : public QWidget {
    Q_OBJECT
public:
    MapsPanel(MaterialDocument* document, BakeRunner* baker, QWidget* parent = nullptr);

    MapRow* row(MapKind kind) const { return m_rows.at(kind); }
    QProgressBar* progressBar() const { return m_progress; }
    QPushButton* cancelButton() const { return m_cancel; }
    QString bakeStatus() const;
    // The bake's line once its map is shown: the bake's own time, where it ran (bakeDevice) and the
    // wait from asking for it to the views drawing with it (a new map can need new shader
    // variants, compiled then).
    void showBakeShown(BakeKind kind, double bakeSeconds, const QString& device,
                       double shownSeconds);
    NormalFilter normalFilter() const;
    double occlusionDistance() const; // +inf: unlimited
    QDoubleSpinBox* occlusionDistanceBox() const { return m_occlusionDistance; }

signals:
    void loadRequested(px::MapKind kind);
    void fileDropped(px::MapKind kind, const QString& path);
    void bakeRequested(px::studio::BakeKind kind);

private:
    void refresh();
    void clearMap(MapKind kind);
    void setBakeStatus(const QString& text);

    MaterialDocument* m_document;
    BakeRunner* m_baker;
    std::map<MapKind, MapRow*> m_rows;
    QComboBox* m_filter;
    QDoubleSpinBox* m_occlusionDistance;
    QLabel* m_bakeLabel;
    QProgressBar* m_progress;
    QPushButton* m_cancel;
};

} // namespace px::studio

#pragma once
// One cell of the viewport grid: a header to pick the viewport's technique and overlays, the
// live preview (or a placeholder), and four lines of figures: technique, frame time, fetches
// per pixel; the technique's error and the filtering's (ErrorStats.h); the share on another
// surface and what was counted; what the errors measure.

#include "preview/PreviewScene.h"

#include <QFrame>

class QAction;
class QLabel;
class QToolButton;

namespace px::studio {

class MaterialDocument;
class PreviewPlaceholder;
class PreviewWidget;
class TechniqueCombo;

class Viewport : public QFrame {
    Q_OBJECT
public:
    // `liveReason` empty: a live preview; otherwise why there is none.
    Viewport(int index, MaterialDocument* document, const QString& liveReason,
             QWidget* parent = nullptr);

    int index() const { return m_index; }
    void setActive(bool active);
    bool isActive() const { return m_active; }

    void setView(const SharedView& view);
    const SharedView& view() const { return m_view; }
    void setOverlays(const ViewOverlays& overlays);
    const ViewOverlays& overlays() const { return m_overlays; }

    PreviewWidget* preview() const { return m_preview; } // null without a live preview
    TechniqueCombo* techniqueCombo() const { return m_technique; }
    TechniqueCombo* wipeCombo() const { return m_wipeTechnique; }
    QToolButton* heatMapButton() const { return m_heatMap; }
    QToolButton* wipeButton() const { return m_wipe; }
    // The heat map's two modes (its button's menu): the technique's error, the filtering's.
    QAction* heatModeAction(HeatMode mode) const;
    QString statsText() const;
    // The line under the figures saying what they measure.
    static QString figuresMeasure();

signals:
    void activated(int index);
    void cameraEdited(int index, const px::studio::OrbitCamera& camera);
    void lightEdited(int index, const px::studio::DirectionalLight& light);
    void overlaysEdited(int index, const px::studio::ViewOverlays& overlays);

protected:
    void mousePressEvent(QMouseEvent* event) override;
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    void refresh();
    void pushScene();
    void showStats();
    void fitStats();
    static QString figuresExplained();
    void editOverlays(const std::function<void(ViewOverlays&)>& change);

    int m_index;
    MaterialDocument* m_document;
    bool m_active = false;
    SharedView m_view;
    ViewOverlays m_overlays;
    QLabel* m_title;
    TechniqueCombo* m_technique;
    QToolButton* m_heatMap;
    QAction* m_heatTechnique;
    QAction* m_heatFiltering;
    QToolButton* m_wipe;
    TechniqueCombo* m_wipeTechnique;
    PreviewWidget* m_preview = nullptr;
    PreviewPlaceholder* m_placeholder = nullptr;
    QLabel* m_stats;
    QString m_figureName;  // the technique's, shown first in bold
    QStringList m_figures; // whole, plain; the first follows the name; m_stats cuts each line
};

} // namespace px::studio

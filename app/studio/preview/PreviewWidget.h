#pragma once
// One viewport's live preview: a QOpenGLWidget whose context the renderer (parallax-render)
// draws the scene into. It also measures the viewport's figures (frame time, fetches per pixel,
// error against the exact intersection) and draws the error heat map and the A/B wipe.
// Mouse: drag orbits, wheel zooms, Ctrl+drag moves the light, dragging the wipe's divider moves it.

#include "parallax/Result.h"
#include "parallax/image/Image.h"
#include "preview/HeatLegend.h"
#include "preview/PreviewScene.h"

#include <QBasicTimer>
#include <QElapsedTimer>
#include <QOpenGLWidget>
#include <cstdint>
#include <memory>
#include <optional>

namespace px {
class GpuMaterial;
class ShaderCache;
} // namespace px

namespace px::studio {

class PreviewRenderer;

class PreviewWidget : public QOpenGLWidget {
    Q_OBJECT
public:
    explicit PreviewWidget(QWidget* parent = nullptr);
    ~PreviewWidget() override;

    void setScene(const PreviewScene& scene);
    const PreviewScene& scene() const { return m_scene; }
    const PreviewStats& stats() const { return m_stats; }
    // The renderer's failure, if the last frame could not be drawn (shader error, GL error).
    QString renderError() const { return m_renderError; }
    // Whole frames drawn so far (tests wait for the next one). A frame that costs more than the
    // pacer's budget (FramePacer.h) is drawn over several turns of the event loop and counts once
    // whole.
    int framesRendered() const { return m_frames; }
    // Whether the last paint showed a whole frame (not the stand-in of one under way).
    bool frameComplete() const { return m_frameComplete; }
    // The value a uniform of the program that drew the last frame holds (tests: sliders reach
    // the GPU). Empty when the program has no such uniform.
    std::optional<float> uniformValue(const QString& name);
    // The maps the last frame drew with; views showing the same maps share them (tests).
    const GpuMaterial* gpuMaterial() const;
    // The compiled variants it draws with, one cache for every view (tests); null before the
    // first frame.
    const ShaderCache* shaderCache() const;
    // Whether the scene's maps are still going up on a worker (the view draws what it has).
    bool uploading() const;
    // Turns of the event loop the figures have taken so far (tests), and the drawing each takes
    // at most (about; 30 ms by default, tests lower it).
    int measureSlices() const { return m_measureSlices; }
    static void setMeasureSliceMs(double ms);

    // `scene` drawn offscreen at `pixels` on this view's context, without the overlays (heat map,
    // messages): a picture to save. Fails without a live preview or over the GL's limits.
    Result<Image> renderImage(const PreviewScene& scene, QSize pixels);

    // Where the heat map's scale is drawn, at this view's size and font (tests).
    HeatLegendLayout heatLegend() const;

    QSize sizeHint() const override { return {320, 240}; }

signals:
    void activated();
    void cameraDragged(const px::studio::OrbitCamera& camera);
    void lightDragged(const px::studio::DirectionalLight& light);
    void wipeDragged(float position);
    void frameRendered();
    void statsChanged();

protected:
    void initializeGL() override;
    void resizeGL(int w, int h) override;
    void paintGL() override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;
    void mouseDoubleClickEvent(QMouseEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;
    void timerEvent(QTimerEvent* event) override;

private:
    enum class Drag { None, Orbit, Light, Wipe };
    void releaseGl();
    // The figures against the exact intersection need two extra passes: taken once the scene
    // has stayed still for a moment, not on every frame of a drag, a slice per event-loop turn.
    void measure();
    void measureSlice();
    void dropMeasurement();
    void drawOverlays(class QPainter& painter, bool heatMap, bool message);
    // Keeps an unfinished frame or measurement going whatever happened to its next step.
    void watch();

    PreviewScene m_scene;
    PreviewStats m_stats;
    QString m_renderError;
    int m_frames = 0;
    std::unique_ptr<PreviewRenderer> m_renderer;
    class QTimer* m_measureTimer;
    class QTimer* m_sliceTimer;
    class QTimer* m_uploadPoll;
    class QTimer* m_continueFrame;
    // While a frame or its figures are unfinished: asks again for whatever step is due where
    // none is on its way (a paint request the platform dropped left a view on its stand-in,
    // "measuring the error…", until the mouse moved). Not a QTimer: nothing else stops it.
    QBasicTimer m_watchdog;
    int m_paintsSinceWatch = 0;
    std::uint64_t m_sceneSerial = 1; // the frame's: a new scene or size starts a new frame
    bool m_frameComplete = false;
    int m_measureSlices = 0;
    bool m_measured = false;
    Drag m_drag = Drag::None;
    QPointF m_lastPos;
};

} // namespace px::studio

#include "preview/PreviewWidget.h"

#include "parallax/render/RenderTarget.h" // parallax-render
#include "preview/FramePacer.h"
#include "preview/HeatLegend.h"
#include "preview/PreviewRenderer.h"
#include "preview/ViewInteraction.h"
#include "widgets/Hints.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QKeyEvent>
#include <QMouseEvent>
#include <QOpenGLContext>
#include <QPainter>
#include <QPointer>
#include <QTimer>
#include <QTimerEvent>
#include <QWheelEvent>
#include <algorithm>
#include <cmath>

namespace px::studio {

namespace {
// How close (logical pixels) a press must be to the wipe divider to grab it.
constexpr double kWipeGrab = 8.0;
// A slice of the measurement's drawing between two turns of the event loop.
double g_measureSliceMs = 30.0;
// Drawing waits this long after the turn that drew last (FramePacer::endTurn).
constexpr qint64 kBreathMs = 10;

// Notes the user's input for FramePacer::inputRecently, whatever widget it goes to.
class InputWatch : public QObject {
public:
    using QObject::QObject;
    bool eventFilter(QObject* watched, QEvent* event) override {
        switch (event->type()) {
        case QEvent::MouseButtonPress:
        case QEvent::MouseButtonDblClick:
        case QEvent::KeyPress:
        case QEvent::Wheel:
        case QEvent::TouchBegin:
            FramePacer::noteInput();
            break;
        default:
            break;
        }
        return QObject::eventFilter(watched, event);
    }
};

void watchInput() {
    static QPointer<InputWatch> watch;
    if (!watch && qApp) {
        watch = new InputWatch(qApp);
        qApp->installEventFilter(watch);
    }
}
} // namespace

void PreviewWidget::setMeasureSliceMs(double ms) {
    g_measureSliceMs = ms;
}

PreviewWidget::PreviewWidget(QWidget* parent) : QOpenGLWidget(parent) {
    watchInput();
    setMinimumSize(96, 72);
    setFocusPolicy(Qt::ClickFocus);
    setStatusTip(hints::viewportHelp());
    setToolTip(hints::viewportHelp());
    m_measureTimer = new QTimer(this);
    m_measureTimer->setSingleShot(true);
    m_measureTimer->setInterval(150);
    connect(m_measureTimer, &QTimer::timeout, this, &PreviewWidget::measure);
    m_sliceTimer = new QTimer(this);
    m_sliceTimer->setSingleShot(true);
    m_sliceTimer->setInterval(0);
    connect(m_sliceTimer, &QTimer::timeout, this, &PreviewWidget::measureSlice);
    m_continueFrame = new QTimer(this);
    m_continueFrame->setSingleShot(true);
    m_continueFrame->setInterval(kBreathMs);
    m_continueFrame->setTimerType(Qt::PreciseTimer); // not early: it would only breathe again
    connect(m_continueFrame, &QTimer::timeout, this, qOverload<>(&PreviewWidget::update));
    // While the maps go up on a worker the view keeps its picture; it draws again when they land.
    m_uploadPoll = new QTimer(this);
    m_uploadPoll->setInterval(50);
    connect(m_uploadPoll, &QTimer::timeout, this, [this] {
        if (!m_renderer || !m_renderer->uploading() || m_renderer->mapsArrived()) {
            m_uploadPoll->stop();
            update();
        }
    });
}

PreviewWidget::~PreviewWidget() {
    releaseGl();
    // ~QOpenGLWidget destroys the context after this part of the object is gone: its
    // aboutToBeDestroyed must not call releaseGl on a PreviewWidget that no longer exists.
    if (QOpenGLContext* gl = context())
        disconnect(gl, nullptr, this, nullptr);
}

void PreviewWidget::releaseGl() {
    if (!m_renderer)
        return;
    makeCurrent();
    m_renderer.reset();
    doneCurrent();
}

void PreviewWidget::setScene(const PreviewScene& scene) {
    m_scene = scene;
    ++m_sceneSerial;
    dropMeasurement();
    m_stats.valid = false;
    m_measureTimer->start();
    update();
    watch();
}

namespace {
// How often an unfinished frame or measurement is looked at: a step is due every turn (tens of
// ms), so a quarter second without one means none is coming.
constexpr int kWatchMs = 250;
} // namespace

void PreviewWidget::watch() {
    if (!m_watchdog.isActive())
        m_watchdog.start(kWatchMs, this);
}

void PreviewWidget::timerEvent(QTimerEvent* event) {
    if (event->timerId() != m_watchdog.timerId()) {
        QOpenGLWidget::timerEvent(event);
        return;
    }
    const bool painted = m_paintsSinceWatch > 0;
    m_paintsSinceWatch = 0;
    if (!m_renderer || !isVisible()) {
        m_watchdog.stop(); // a view shown again paints, and watches again
        return;
    }
    if (!m_frameComplete || m_renderer->uploading()) {
        if (!painted)
            update(); // the frame's next step was asked for and never came
        return;
    }
    if (m_measured) {
        m_watchdog.stop(); // the frame and its figures are done
        return;
    }
    // The figures: their next slice, or their start, where none is on its way.
    if (m_renderer->measuring()) {
        if (!m_sliceTimer->isActive())
            measureSlice();
    } else if (!m_measureTimer->isActive()) {
        measure();
    }
}

void PreviewWidget::dropMeasurement() {
    m_measured = false;
    m_sliceTimer->stop();
    if (m_renderer)
        m_renderer->cancelMeasure();
}

void PreviewWidget::measure() {
    if (!m_renderer || !isVisible() || !m_frameComplete)
        return; // paintGL asks again once the frame is whole
    makeCurrent();
    const Status begun =
        m_renderer->beginMeasure(m_scene, size() * devicePixelRatioF(), m_stats.frameMs);
    doneCurrent();
    if (!begun) {
        m_renderError = QString::fromStdString(begun.error().message);
        update();
        return;
    }
    measureSlice();
}

void PreviewWidget::measureSlice() {
    if (!m_renderer || !isVisible()) {
        dropMeasurement(); // again when it shows
        return;
    }
    // The views' frames and measurements share a turn's budget (FramePacer): a slice waits for
    // the next turn rather than start a box the turn has no room left for.
    const double left = FramePacer::budgetLeftInTurn(kBreathMs);
    if (left < FramePacer::budgetMs() && left < std::max(1.0, m_renderer->measureBoxMs())) {
        m_sliceTimer->start(kBreathMs);
        return;
    }
    QElapsedTimer clock;
    clock.start();
    makeCurrent();
    std::optional<Result<PreviewStats>> measured =
        m_renderer->measureStep(std::min(g_measureSliceMs, left));
    doneCurrent();
    FramePacer::spentInTurn(static_cast<double>(clock.nsecsElapsed()) / 1e6);
    QMetaObject::invokeMethod(
        this, [] { FramePacer::endTurn(); }, Qt::QueuedConnection);
    ++m_measureSlices;
    if (!measured) {
        // The rest after the events waiting; later while a pass waits for the user to pause.
        m_sliceTimer->start(m_renderer->measureWaitsForInput() ? 50 : 0);
        return;
    }
    const Result<PreviewStats>& stats = *measured;
    m_measured = !m_renderer->uploading(); // else again once the maps are up
    if (stats)
        m_stats = *stats;
    else
        m_renderError = QString::fromStdString(stats.error().message);
    update();
    emit statsChanged();
}

std::optional<float> PreviewWidget::uniformValue(const QString& name) {
    if (!m_renderer)
        return std::nullopt;
    makeCurrent();
    std::optional<float> value = m_renderer->uniformValue(name.toStdString());
    doneCurrent();
    return value;
}

const GpuMaterial* PreviewWidget::gpuMaterial() const {
    return m_renderer ? m_renderer->gpuMaterial() : nullptr;
}

const ShaderCache* PreviewWidget::shaderCache() const {
    return m_renderer ? &m_renderer->shaders() : nullptr;
}

bool PreviewWidget::uploading() const {
    return m_renderer && m_renderer->uploading();
}

Result<Image> PreviewWidget::renderImage(const PreviewScene& scene, QSize pixels) {
    if (!m_renderer)
        return Error{"there is no live preview to render with"};
    makeCurrent();
    Result<RenderTarget> target =
        RenderTarget::create({pixels.width(), pixels.height()}, TargetFormat::Rgba8);
    Result<Image> image = target ? Result<Image>(Image()) : Result<Image>(target.error());
    if (target) {
        Result<double> drawn = m_renderer->draw(scene, pixels, target->framebuffer());
        if (drawn && m_renderer->uploading()) { // a picture of the scene's own maps
            m_renderer->waitForMaps();
            drawn = m_renderer->draw(scene, pixels, target->framebuffer());
        }
        image = drawn ? Result<Image>(target->read()) : Result<Image>(drawn.error());
    }
    doneCurrent();
    return image;
}

void PreviewWidget::initializeGL() {
    // The context goes away with the widget's top level window (reparenting, closing): the
    // renderer's GL objects must go first.
    connect(context(), &QOpenGLContext::aboutToBeDestroyed, this, &PreviewWidget::releaseGl,
            Qt::UniqueConnection);
    Result<std::unique_ptr<PreviewRenderer>> renderer = PreviewRenderer::create();
    if (!renderer) {
        m_renderError = QString::fromStdString(renderer.error().message);
        return;
    }
    m_renderer = std::move(*renderer);
    m_renderError.clear();
}

void PreviewWidget::resizeGL(int, int) {
    ++m_sceneSerial;
    dropMeasurement(); // measured again at the new size
}

void PreviewWidget::paintGL() {
    ++m_paintsSinceWatch;
    watch();
    const QSize pixels = size() * devicePixelRatioF();
    // The renderer's raw GL between begin/endNativePainting, as Qt asks of mixed painting.
    QPainter painter(this);
    painter.beginNativePainting();
    bool complete = false;
    if (m_renderer) {
        // Nothing is drawn within a breath of the turn that drew last (FramePacer::endTurn):
        // what came meanwhile, input, timers, is handled first.
        const double budget = FramePacer::budgetLeftInTurn(kBreathMs);
        QElapsedTimer stepClock;
        stepClock.start();
        Result<FramePacer::Step> step =
            m_renderer->drawStep(m_scene, m_sceneSerial, pixels, defaultFramebufferObject(),
                                 budget < 1.0 ? 0.0 : budget);
        FramePacer::spentInTurn(static_cast<double>(stepClock.nsecsElapsed()) / 1e6);
        if (!step) {
            m_renderError = QString::fromStdString(step.error().message);
            complete = true;
        } else {
            m_renderError.clear();
            complete = step->complete;
            if (complete) {
                m_stats.frameMs = step->frameMs;
                ++m_frames;
            }
        }
        // The turn ends after this paint event, composing included; the rest of the frame a
        // breath later.
        QMetaObject::invokeMethod(
            this,
            [this, complete] {
                FramePacer::endTurn();
                if (!complete)
                    m_continueFrame->start();
            },
            Qt::QueuedConnection);
        if (m_renderer->uploading()) {
            // Drawn with the maps there were: again once the scene's are up, then measured.
            m_measured = false;
            if (!m_uploadPoll->isActive())
                m_uploadPoll->start();
        } else if (complete && !m_measured && !m_measureTimer->isActive() &&
                   !m_renderer->measuring()) {
            m_measureTimer->start();
        }
    }
    m_frameComplete = complete;
    painter.endNativePainting();

    const bool heatMap = m_renderer && m_scene.overlays.heatMap && m_stats.valid;
    if (heatMap) {
        const QImage heat = m_renderer->heatMap();
        if (!heat.isNull()) {
            painter.setRenderHint(QPainter::SmoothPixmapTransform, false);
            painter.drawImage(rect(), heat);
        }
    }
    const bool message = !m_renderError.isEmpty() || !m_scene.traceable;
    if (heatMap || m_scene.overlays.wipe || message) {
        // Text drawn by the GL paint engine after the renderer's GL came out upside down (its
        // glyph cache, on Mesa at scales 1 and 2); drawn by the raster engine into an image and
        // composited as one, it is upright on every driver.
        QImage overlay(pixels, QImage::Format_ARGB32_Premultiplied);
        overlay.setDevicePixelRatio(devicePixelRatioF());
        overlay.fill(Qt::transparent);
        QPainter text(&overlay);
        drawOverlays(text, heatMap, message);
        text.end();
        painter.drawImage(QPointF(0, 0), overlay);
    }
    painter.end();
    if (complete) {
        emit frameRendered();
        emit statsChanged(); // the frame time
    }
}

void PreviewWidget::drawOverlays(QPainter& painter, bool heatMap, bool message) {
    painter.setFont(font());
    if (heatMap)
        drawHeatLegend(painter, heatLegend());
    if (m_scene.overlays.wipe) {
        const double x = m_scene.overlays.wipePosition * width();
        painter.setPen(QPen(Qt::white, 2));
        painter.drawLine(QPointF(x, 0), QPointF(x, height()));
        painter.setPen(Qt::white);
        const QString a = QString::fromUtf8(info(m_scene.quality.technique).name.data());
        const QString b = QString::fromUtf8(info(m_scene.overlays.wipeTechnique).name.data());
        painter.drawText(QRectF(0, 4, x - 6, 20), Qt::AlignRight, a);
        painter.drawText(QRectF(x + 6, 4, width() - x - 6, 20), Qt::AlignLeft, b);
    }
    if (message) {
        painter.fillRect(rect(), QColor(0, 0, 0, 160));
        painter.setPen(Qt::white);
        const QString text =
            !m_scene.traceable
                ? tr("%1 needs maps this material does not have yet.")
                      .arg(QString::fromUtf8(info(m_scene.quality.technique).title.data()))
                : m_renderError;
        painter.drawText(rect().adjusted(10, 10, -10, -10), Qt::AlignCenter | Qt::TextWordWrap,
                         text);
    }
}

HeatLegendLayout PreviewWidget::heatLegend() const {
    return layoutHeatLegend(QFontMetrics(font()), size());
}

void PreviewWidget::mousePressEvent(QMouseEvent* event) {
    emit activated();
    m_lastPos = event->position();
    const double divider = m_scene.overlays.wipePosition * width();
    if (m_scene.overlays.wipe && std::abs(event->position().x() - divider) <= kWipeGrab)
        m_drag = Drag::Wipe;
    else if (event->modifiers() & Qt::ControlModifier)
        m_drag = Drag::Light;
    else
        m_drag = Drag::Orbit;
    event->accept();
}

void PreviewWidget::mouseMoveEvent(QMouseEvent* event) {
    const QPointF delta = event->position() - m_lastPos;
    m_lastPos = event->position();
    switch (m_drag) {
    case Drag::Orbit:
        emit cameraDragged(orbit(m_scene.view.camera, delta));
        break;
    case Drag::Light:
        emit lightDragged(moveLight(m_scene.view.light, delta));
        break;
    case Drag::Wipe:
        emit wipeDragged(
            static_cast<float>(std::clamp(event->position().x() / std::max(1, width()), 0.0, 1.0)));
        break;
    case Drag::None:
        break;
    }
}

void PreviewWidget::mouseReleaseEvent(QMouseEvent*) {
    m_drag = Drag::None;
}

void PreviewWidget::mouseDoubleClickEvent(QMouseEvent* event) {
    emit cameraDragged(framed(defaultCamera(), m_scene.view,
                              height() > 0 ? float(width()) / float(height()) : 1.0f));
    event->accept();
}

void PreviewWidget::keyPressEvent(QKeyEvent* event) {
    // Arrows orbit (Ctrl: move the light), +/- zoom: the view without a mouse.
    const double step = 10.0 / kDegreesPerPixel; // ten degrees
    QPointF delta;
    switch (event->key()) {
    case Qt::Key_Left:
        delta = {-step, 0};
        break;
    case Qt::Key_Right:
        delta = {step, 0};
        break;
    case Qt::Key_Up:
        delta = {0, -step};
        break;
    case Qt::Key_Down:
        delta = {0, step};
        break;
    case Qt::Key_Plus:
    case Qt::Key_Equal:
        emit cameraDragged(zoom(m_scene.view.camera, 1));
        return;
    case Qt::Key_Minus:
        emit cameraDragged(zoom(m_scene.view.camera, -1));
        return;
    default:
        QOpenGLWidget::keyPressEvent(event);
        return;
    }
    if (event->modifiers() & Qt::ControlModifier)
        emit lightDragged(moveLight(m_scene.view.light, delta));
    else
        emit cameraDragged(orbit(m_scene.view.camera, delta));
}

void PreviewWidget::wheelEvent(QWheelEvent* event) {
    emit cameraDragged(zoom(m_scene.view.camera, event->angleDelta().y() / 120.0));
    event->accept();
}

} // namespace px::studio

#include "preview/PreviewPlaceholder.h"

#include <QPainter>

namespace px::studio {

PreviewPlaceholder::PreviewPlaceholder(const QString& reason, QWidget* parent)
    : QWidget(parent), m_reason(reason) {
    setMinimumSize(160, 120);
    setToolTip(reason);
}

void PreviewPlaceholder::setImage(const QImage& image) {
    m_image = image;
    update();
}

void PreviewPlaceholder::paintEvent(QPaintEvent*) {
    QPainter p(this);
    p.fillRect(rect(), palette().color(QPalette::Dark));
    if (!m_image.isNull()) {
        // Tiled the way the material tiles, dimmed so the message reads.
        p.setOpacity(0.5);
        const QSize side = m_image.size().scaled(rect().size() / 2, Qt::KeepAspectRatio);
        p.drawTiledPixmap(rect(), QPixmap::fromImage(m_image.scaled(side, Qt::KeepAspectRatio,
                                                                    Qt::SmoothTransformation)));
        p.setOpacity(1.0);
    }
    p.setPen(palette().color(QPalette::BrightText));
    p.drawText(rect().adjusted(12, 12, -12, -12), Qt::AlignCenter | Qt::TextWordWrap,
               tr("No live preview\n%1").arg(m_reason));
}

} // namespace px::studio

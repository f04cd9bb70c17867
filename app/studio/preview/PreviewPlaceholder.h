#pragma once
// What a viewport shows where there is no live preview (offscreen platform, no OpenGL 4.3): the
// material's colour map, and why there is no preview.

#include <QImage>
#include <QWidget>

namespace px::studio {

class PreviewPlaceholder : public QWidget {
    Q_OBJECT
public:
    PreviewPlaceholder(const QString& reason, QWidget* parent = nullptr);
    void setImage(const QImage& image);

protected:
    void paintEvent(QPaintEvent* event) override;

private:
    QString m_reason;
    QImage m_image;
};

} // namespace px::studio

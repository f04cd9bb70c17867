// Thumbnails: every texel of a box counts once (a one-texel checker is grey, not aliased to
// black or white), colours keep their order, and a grey map reads as grey.

#include "widgets/ImageConvert.h"

#include <QTest>
#include <random>

using namespace px;
using namespace px::studio;

class ImageConvertTest : public QObject {
    Q_OBJECT
private slots:
    void boxesAverageEveryTexel() {
        // 300 x 200 into 40: boxes of 8 x 8 (37 x 25 of them), the right and bottom rest dropped.
        HeightField checker(300, 200);
        for (int y = 0; y < 200; ++y)
            for (int x = 0; x < 300; ++x)
                checker.at(x, y) = float((x + y) % 2);
        const QImage grey = toQImage(checker, 40);
        QCOMPARE(grey.size(), QSize(37, 25));
        for (int y = 0; y < grey.height(); ++y)
            for (int x = 0; x < grey.width(); ++x)
                QCOMPARE(grey.pixel(x, y), qRgb(128, 128, 128));

        // Random texels: each thumbnail pixel is its box's mean, to 8 bits.
        std::mt19937 rng(4242);
        std::uniform_real_distribution<float> unit(0.0f, 1.0f);
        Image colour(96, 64, 3);
        for (float& v : colour.pixels)
            v = unit(rng);
        const QImage small = toQImage(colour, 24);
        QCOMPARE(small.size(), QSize(24, 16));
        for (int y = 0; y < small.height(); ++y) {
            for (int x = 0; x < small.width(); ++x) {
                for (int c = 0; c < 3; ++c) {
                    double sum = 0.0;
                    for (int sy = 4 * y; sy < 4 * y + 4; ++sy)
                        for (int sx = 4 * x; sx < 4 * x + 4; ++sx)
                            sum += colour.at(sx, sy, c);
                    const QRgb p = small.pixel(x, y);
                    const int got = c == 0 ? qRed(p) : c == 1 ? qGreen(p) : qBlue(p);
                    QVERIFY2(std::abs(got - sum / 16.0 * 255.0) <= 0.51,
                             qPrintable(QString("pixel (%1, %2) channel %3").arg(x).arg(y).arg(c)));
                }
            }
        }
    }
};

QTEST_APPLESS_MAIN(ImageConvertTest)
#include "ImageConvertTest.moc"

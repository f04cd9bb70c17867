// Floats as the shortest decimal that reads back to them: what material files and engine exports
// print. Checked on chosen values and on 200 000 random floats of every magnitude.

#include "io/ShortestDecimal.h"

#include <QtTest>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <random>

using namespace px;

namespace {

int significantDigits(double value) {
    char text[40];
    for (int digits = 1; digits <= 17; ++digits) {
        std::snprintf(text, sizeof text, "%.*g", digits, value);
        if (std::strtod(text, nullptr) == value)
            return digits;
    }
    return 17;
}

} // namespace

class ShortestDecimalTest : public QObject {
    Q_OBJECT

private slots:
    void chosenValues_data();
    void chosenValues();
    void randomFloatsReadBack();
};

void ShortestDecimalTest::chosenValues_data() {
    QTest::addColumn<float>("value");
    QTest::addColumn<double>("expected");
    QTest::newRow("0.05") << 0.05f << 0.05;
    QTest::newRow("0.6") << 0.6f << 0.6;
    QTest::newRow("1") << 1.0f << 1.0;
    QTest::newRow("0") << 0.0f << 0.0;
    QTest::newRow("-0.3") << -0.3f << -0.3;
    QTest::newRow("1/3") << 1.0f / 3.0f << 0.33333334; // needs 8 digits
    QTest::newRow("2^24") << 16777216.0f << 16777216.0;
    QTest::newRow("tiny") << 1e-30f << 1e-30;
    QTest::newRow("huge") << 3.4e38f << 3.4e38;
}

void ShortestDecimalTest::chosenValues() {
    QFETCH(float, value);
    QFETCH(double, expected);
    QCOMPARE(shortestDecimal(value), expected);
}

void ShortestDecimalTest::randomFloatsReadBack() {
    std::mt19937 random(20261123);
    std::uniform_int_distribution<std::uint32_t> bits(0, 0xffffffffu);
    int checked = 0;
    for (int i = 0; i < 200000; ++i) {
        const float value = std::bit_cast<float>(bits(random));
        if (!std::isfinite(value))
            continue;
        const double d = shortestDecimal(value);
        // Reads back to the same float, and is no longer than 9 significant digits (a float
        // never needs more).
        if (static_cast<float>(d) != value || significantDigits(d) > 9)
            QFAIL(qPrintable(QString("%1 -> %2").arg(value, 0, 'g', 9).arg(d, 0, 'g', 17)));
        ++checked;
    }
    QVERIFY(checked > 190000);
}

QTEST_APPLESS_MAIN(ShortestDecimalTest)
#include "ShortestDecimalTest.moc"

// The DFT of any length (core/src/bake/Dft.h) against the direct O(n²) sum: every length 1 to 260
// (primes, prime powers, products with large prime factors) and a few large primes, both ways,
// on random data (seed varies per run; PX_TEST_SEED=N repeats one). Lengths with a prime factor
// over 5 take Bluestein's padded path; the rest kissfft as is.

#include "bake/Dft.h"

#include <QtTest>
#include <cstdlib>
#include <random>

using px::bake::Dft;
using Complex = Dft::Complex;

class DftTest : public QObject {
    Q_OBJECT

private slots:
    void equalsTheDirectSum();
    void paddedWhereKissfftIsQuadratic();
};

namespace {

std::vector<Complex> direct(const std::vector<Complex>& x, bool inverse) {
    const std::size_t n = x.size();
    std::vector<Complex> out(n);
    const double sign = inverse ? 1.0 : -1.0;
    for (std::size_t k = 0; k < n; ++k) {
        Complex sum(0.0);
        for (std::size_t j = 0; j < n; ++j) {
            const double turn = static_cast<double>((j * k) % n) / static_cast<double>(n);
            sum += x[j] * std::polar(1.0, sign * 2.0 * std::numbers::pi * turn);
        }
        out[k] = sum;
    }
    return out;
}

} // namespace

void DftTest::equalsTheDirectSum() {
    const char* given = std::getenv("PX_TEST_SEED");
    const unsigned seed = given ? static_cast<unsigned>(std::strtoul(given, nullptr, 10))
                                : std::random_device{}() % 100000u;
    qInfo("seed %u (PX_TEST_SEED=%u repeats it)", seed, seed);
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> value(-1.0, 1.0);
    std::vector<int> lengths;
    for (int n = 1; n <= 260; ++n)
        lengths.push_back(n);
    for (const int n : {509, 1021, 2042})
        lengths.push_back(n);
    int padded = 0;
    for (const int n : lengths) {
        std::vector<Complex> x(static_cast<std::size_t>(n));
        for (Complex& c : x)
            c = {value(random), value(random)};
        for (const bool inverse : {false, true}) {
            const Dft dft(n, inverse);
            padded += dft.padded() && !inverse;
            // NOLINTNEXTLINE(performance-unnecessary-copy-initialization): the copy is tested
            const Dft copy = dft; // as each thread takes one
            std::vector<Complex> out(x.size()), work;
            copy.transform(x.data(), out.data(), work);
            const std::vector<Complex> expected = direct(x, inverse);
            double worst = 0.0, scale = 0.0;
            for (std::size_t k = 0; k < x.size(); ++k) {
                worst = std::max(worst, std::abs(out[k] - expected[k]));
                scale = std::max(scale, std::abs(expected[k]));
            }
            QVERIFY2(worst <= 1e-10 * std::max(scale, 1.0),
                     qPrintable(QString("n %1 %2: off by %3 of %4")
                                    .arg(n)
                                    .arg(inverse ? "inverse" : "forward")
                                    .arg(worst)
                                    .arg(scale)));
        }
    }
    QVERIFY(padded > 100); // most lengths up to 260 have a prime factor over 5
}

void DftTest::paddedWhereKissfftIsQuadratic() {
    for (const int n : {7, 1021, 8191, 2 * 1021, 1000 * 7})
        QVERIFY2(Dft(n, false).padded(), qPrintable(QString::number(n)));
    for (const int n : {1, 2, 1024, 1000, 3 * 5 * 2048, 8192})
        QVERIFY2(!Dft(n, false).padded(), qPrintable(QString::number(n)));
    // Bluestein's power of two covers the linear convolution (2n - 1) and no more than twice it.
    for (const int n : {7, 1021, 8191}) {
        const int m = Dft::paddedLength(n);
        QVERIFY(m >= 2 * n - 1 && m < 4 * n - 2 && (m & (m - 1)) == 0);
    }
}

QTEST_APPLESS_MAIN(DftTest)
#include "DftTest.moc"

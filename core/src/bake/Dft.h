#pragma once
// The discrete Fourier transform of any length n in O(n log n). kissfft is fast on lengths whose
// prime factors are 2, 3 and 5; on others it falls back to an O(p^2) pass per factor p, so a prime
// length (1021, 8191) costs O(n^2): 16 s instead of 1 s for a 1021² map, over an hour at 8191².
// Those lengths go through Bluestein's chirp-z identity (1968): nk = (n² + k² - (k - n)²) / 2
// turns the DFT into a convolution with a chirp, done by power-of-two transforms of length
// M >= 2n - 1. Unnormalised both ways, as kissfft: inverse(forward(x)) = n x.
//
// Not to be shared between threads (kissfft's transform keeps scratch); copy one per thread.

#include <algorithm>
#include <complex>
#include <kissfft/kissfft.hh>
#include <numbers>
#include <vector>

namespace px::bake {

class Dft {
public:
    using Complex = std::complex<double>;

    Dft(int n, bool inverse)
        : m_n(n), m_m(paddedLength(n)), m_direct(m_m > 0 ? 1 : n, inverse),
          m_forwardM(std::max(m_m, 1), false), m_inverseM(std::max(m_m, 1), true) {
        if (m_m == 0)
            return;
        // w_j = e^{∓iπ j²/n}, j² taken mod 2n so the angle stays exact for large n.
        m_chirp.resize(static_cast<std::size_t>(n));
        const double sign = inverse ? 1.0 : -1.0;
        for (long long j = 0; j < n; ++j) {
            const long long j2 = (j * j) % (2LL * n);
            m_chirp[static_cast<std::size_t>(j)] =
                std::polar(1.0, sign * std::numbers::pi * static_cast<double>(j2) / n);
        }
        // The convolution kernel conj(w) laid out circularly, transformed once.
        const auto m = static_cast<std::size_t>(m_m);
        std::vector<Complex> kernel(m, Complex(0.0));
        for (std::size_t j = 0; j < static_cast<std::size_t>(n); ++j) {
            kernel[j] = std::conj(m_chirp[j]);
            if (j > 0)
                kernel[m - j] = kernel[j];
        }
        m_kernel.resize(m);
        m_forwardM.transform(kernel.data(), m_kernel.data());
    }

    // Whether kissfft is used as is (every prime factor 2, 3 or 5).
    static bool direct(int n) {
        for (const int p : {2, 3, 5}) {
            while (n > 1 && n % p == 0)
                n /= p;
        }
        return n == 1;
    }
    bool padded() const { return m_m > 0; }
    // The power of two Bluestein's convolution runs at, or 0 where kissfft runs as is.
    static int paddedLength(int n) {
        if (direct(n))
            return 0;
        int m = 1;
        while (m < 2 * n - 1)
            m *= 2;
        return m;
    }

    // out = DFT(in), n values each; `work` is scratch (2M values when padded).
    void transform(const Complex* in, Complex* out, std::vector<Complex>& work) const {
        if (!padded()) {
            m_direct.transform(in, out);
            return;
        }
        const auto m = static_cast<std::size_t>(m_m);
        work.assign(2 * m, Complex(0.0));
        Complex* a = work.data();
        Complex* spectrum = a + m;
        for (int j = 0; j < m_n; ++j)
            a[j] = in[j] * m_chirp[static_cast<std::size_t>(j)];
        m_forwardM.transform(a, spectrum);
        for (std::size_t k = 0; k < m; ++k)
            spectrum[k] *= m_kernel[k];
        m_inverseM.transform(spectrum, a);
        const double norm = 1.0 / static_cast<double>(m);
        for (int k = 0; k < m_n; ++k)
            out[k] = a[k] * m_chirp[static_cast<std::size_t>(k)] * norm;
    }

private:
    int m_n = 0, m_m = 0;
    kissfft<double> m_direct;
    kissfft<double> m_forwardM, m_inverseM; // length m_m
    std::vector<Complex> m_chirp, m_kernel;
};

} // namespace px::bake

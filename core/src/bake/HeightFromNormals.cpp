#include "parallax/bake/HeightFromNormals.h"

#include "bake/BakeProgress.h"
#include "bake/Dft.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <tbb/parallel_for.h>
#include <vector>

namespace px {

namespace {

using Complex = std::complex<double>;

// One axis of the separable transform: the DFT of length n (periodic), or the DCT-II of length n
// through a DFT of length 2n (Makhoul's mirror: the even extension has only cosines), each
// O(n log n) at any n (Dft.h). Not to be shared between threads: kissfft's const transform()
// writes a mutable scratch buffer for factors other than 2-5 (a shared one gave wrong heights in
// 5 runs of 12), and so does the Dft's, so each parallel chunk copies.
class AxisTransform {
public:
    AxisTransform(int n, bool periodic)
        : m_n(n), m_periodic(periodic), m_forward(periodic ? n : 2 * n, false),
          m_inverse(periodic ? n : 2 * n, true) {}

    // The eigenvalue of the 1-D second difference for frequency k: 2 - 2 cos(theta).
    double eigenvalue(int k) const {
        const double theta = (m_periodic ? 2.0 : 1.0) * std::numbers::pi * k / m_n;
        return 2.0 - 2.0 * std::cos(theta);
    }

    // In place on n values spaced `stride` apart; `scratch` holds 4n.
    void forward(Complex* data, std::size_t stride, std::vector<Complex>& scratch) const {
        transform(data, stride, scratch, false);
    }
    void inverse(Complex* data, std::size_t stride, std::vector<Complex>& scratch) const {
        transform(data, stride, scratch, true);
    }

private:
    void transform(Complex* data, std::size_t stride, std::vector<Complex>& scratch,
                   bool back) const {
        const int n = m_n;
        const int m = m_periodic ? n : 2 * n;
        scratch.resize(2 * static_cast<std::size_t>(m));
        Complex* in = scratch.data();
        Complex* out = in + m;
        if (m_periodic) {
            for (int i = 0; i < n; ++i)
                in[i] = data[i * stride];
            (back ? m_inverse : m_forward).transform(in, out, m_work);
            const double norm = back ? 1.0 / n : 1.0;
            for (int i = 0; i < n; ++i)
                data[i * stride] = out[i] * norm;
            return;
        }
        const double pi = std::numbers::pi;
        if (!back) {
            // X_k = 1/2 e^{-i pi k / 2n} Y_k, Y the DFT of x followed by x reversed.
            for (int i = 0; i < n; ++i)
                in[i] = in[2 * n - 1 - i] = data[i * stride].real();
            m_forward.transform(in, out, m_work);
            for (int k = 0; k < n; ++k)
                data[k * stride] = 0.5 * (std::polar(1.0, -pi * k / (2.0 * n)) * out[k]).real();
            return;
        }
        // x_n = 1/n Re sum_k c_k X_k e^{i pi k (n + 1/2) / n}, c_0 = 1, c_k = 2.
        for (int k = 0; k < 2 * n; ++k)
            in[k] = k < n ? (k == 0 ? 1.0 : 2.0) * data[k * stride].real() *
                                std::polar(1.0, pi * k / (2.0 * n))
                          : Complex(0.0);
        m_inverse.transform(in, out, m_work);
        for (int i = 0; i < n; ++i)
            data[i * stride] = out[i].real() / n;
    }

    int m_n;
    bool m_periodic;
    bake::Dft m_forward, m_inverse;
    mutable std::vector<Complex> m_work; // the Dft's scratch
};

// Solves (Dx'Dx + Dy'Dy) h = f for h with zero mean, Dx and Dy forward differences with
// periodic or free borders.
void solvePoisson(std::vector<Complex>& f, int W, int H, bool periodic, BakeProgress& progress) {
    const AxisTransform tx(W, periodic), ty(H, periodic);
    auto rows = [&](bool back) {
        tbb::parallel_for(tbb::blocked_range<int>(0, H, 16), [&](const tbb::blocked_range<int>& r) {
            // NOLINTNEXTLINE(performance-unnecessary-copy-initialization): the copy is the point
            const AxisTransform t = tx; // see AxisTransform: one per thread
            std::vector<Complex> scratch;
            for (int y = r.begin(); y < r.end(); ++y) {
                Complex* row = f.data() + static_cast<std::size_t>(y) * W;
                back ? t.inverse(row, 1, scratch) : t.forward(row, 1, scratch);
            }
            progress.advance(r.size());
        });
    };
    auto columns = [&](bool back) {
        tbb::parallel_for(tbb::blocked_range<int>(0, W, 16), [&](const tbb::blocked_range<int>& r) {
            // NOLINTNEXTLINE(performance-unnecessary-copy-initialization): the copy is the point
            const AxisTransform t = ty; // see AxisTransform: one per thread
            std::vector<Complex> scratch;
            for (int x = r.begin(); x < r.end(); ++x)
                back ? t.inverse(f.data() + x, W, scratch) : t.forward(f.data() + x, W, scratch);
            progress.advance(r.size());
        });
    };
    rows(false);
    columns(false);
    tbb::parallel_for(0, H, [&](int l) {
        const double ly = ty.eigenvalue(l);
        for (int k = 0; k < W; ++k) {
            const double lambda = tx.eigenvalue(k) + ly;
            Complex& c = f[static_cast<std::size_t>(l) * W + k];
            c = lambda > 1e-12 ? c / lambda : Complex(0.0); // the mean is free: zero
        }
    });
    columns(true);
    rows(true);
}

// Does the map tile? Its seams (the steps from the last column to the first, and the last row to
// the first) against the steps inside.
bool tiles(const Image& n) {
    auto step = [&](int x0, int y0, int x1, int y1) {
        double d = 0.0;
        for (int c = 0; c < 3; ++c)
            d += std::abs(n.at(x0, y0, c) - n.at(x1, y1, c));
        return d;
    };
    double seam = 0.0, inside = 0.0;
    for (int y = 0; y < n.height; ++y) {
        seam += step(n.width - 1, y, 0, y);
        inside += step(n.width / 2 - 1, y, n.width / 2, y);
    }
    for (int x = 0; x < n.width; ++x) {
        seam += step(x, n.height - 1, x, 0);
        inside += step(x, n.height / 2 - 1, x, n.height / 2);
    }
    return seam <= 2.0 * inside + 1e-6;
}

} // namespace

Result<DerivedHeight> heightFromNormals(const Image& normals,
                                        const HeightFromNormalsOptions& options,
                                        const BakeControl& control) {
    if (normals.channels < 3)
        return Error{"a normal map needs red, green and blue channels"};
    const int W = normals.width, H = normals.height;
    if (W < 2 || H < 2)
        return Error{"the normal map is too small to integrate (" + std::to_string(W) + "x" +
                     std::to_string(H) + ")"};
    DerivedHeight out;

    // Slopes in uv units per texel step: dh/du = -nx/nz, dh/dv = +ny/nz under OpenGL green
    // (docs/conventions.md §3), less the mean slope unless it is kept. Computed where needed, not
    // stored: an 8192² map holds only f.
    const double greenSign = options.green == NormalGreen::OpenGL ? 1.0 : -1.0;
    const std::size_t N = static_cast<std::size_t>(W) * H;
    auto nz = [&](int x, int y) { return std::max(2.0 * normals.at(x, y, 2) - 1.0, 0.05); };
    double tiltP = 0.0, tiltQ = 0.0;
    auto p = [&](int x, int y) {
        return -(2.0 * normals.at(x, y, 0) - 1.0) / nz(x, y) / W - tiltP;
    };
    auto q = [&](int x, int y) {
        return greenSign * (2.0 * normals.at(x, y, 1) - 1.0) / nz(x, y) / H - tiltQ;
    };
    double meanP = 0.0, meanQ = 0.0;
    for (int y = 0; y < H; ++y) {
        for (int x = 0; x < W; ++x) {
            meanP += p(x, y);
            meanQ += q(x, y);
        }
    }
    meanP /= static_cast<double>(N);
    meanQ /= static_cast<double>(N);
    // A map tiles when its seams are like its inside. With its mean slope removed, that is all:
    // a biased normal map of a tiling set tiles. A kept slope (a ramp, whose normals tile too)
    // cannot be periodic: then only a map that does not climb on average tiles.
    double rmsP = 0.0, rmsQ = 0.0;
    if (options.keepTilt) {
        for (int y = 0; y < H; ++y) {
            for (int x = 0; x < W; ++x) {
                rmsP += p(x, y) * p(x, y);
                rmsQ += q(x, y) * q(x, y);
            }
        }
        rmsP = std::sqrt(rmsP / static_cast<double>(N));
        rmsQ = std::sqrt(rmsQ / static_cast<double>(N));
    }
    const bool level = !options.keepTilt || (std::abs(meanP) <= 0.1 * rmsP + 1e-12 &&
                                             std::abs(meanQ) <= 0.1 * rmsQ + 1e-12);
    out.periodic = options.periodic ? *options.periodic : level && tiles(normals);
    if (!options.keepTilt || out.periodic) {
        tiltP = meanP;
        tiltQ = meanQ;
        out.tiltU = meanP * W;
        out.tiltV = meanQ * H;
    }
    // b = the slope of each step (x to x+1, y to y+1), averaged from the texel centres at its
    // ends; free borders have no step past the edge.
    const bool periodic = out.periodic;
    auto bx = [&](int x, int y) {
        if (x < 0)
            x = periodic ? W - 1 : -1;
        if (x < 0 || (!periodic && x + 1 >= W))
            return 0.0;
        return 0.5 * (p(x, y) + p((x + 1) % W, y));
    };
    auto by = [&](int x, int y) {
        if (y < 0)
            y = periodic ? H - 1 : -1;
        if (y < 0 || (!periodic && y + 1 >= H))
            return 0.0;
        return 0.5 * (q(x, y) + q(x, (y + 1) % H));
    };
    auto idx = [W](int x, int y) { return static_cast<std::size_t>(y) * W + x; };
    // f = D'b: what flows in from the step before minus what flows out.
    std::vector<Complex> f(N);
    tbb::parallel_for(0, H, [&](int y) {
        for (int x = 0; x < W; ++x)
            f[idx(x, y)] = bx(x - 1, y) - bx(x, y) + by(x, y - 1) - by(x, y);
    });
    BakeProgress progress(control, 2 * (static_cast<std::int64_t>(W) + H));
    solvePoisson(f, W, H, out.periodic, progress);
    if (progress.stopRequested())
        return cancelledError();

    // The misfit, and the relief spread over [0, 1].
    double lo = 1e300, hi = -1e300, miss = 0.0, total = 0.0;
    for (std::size_t i = 0; i < N; ++i) {
        lo = std::min(lo, f[i].real());
        hi = std::max(hi, f[i].real());
    }
    for (int y = 0; y < H; ++y) {
        for (int x = 0; x < W; ++x) {
            if (periodic || x + 1 < W) {
                const double d = f[idx((x + 1) % W, y)].real() - f[idx(x, y)].real();
                miss += (d - bx(x, y)) * (d - bx(x, y));
                total += bx(x, y) * bx(x, y);
            }
            if (periodic || y + 1 < H) {
                const double d = f[idx(x, (y + 1) % H)].real() - f[idx(x, y)].real();
                miss += (d - by(x, y)) * (d - by(x, y));
                total += by(x, y) * by(x, y);
            }
        }
    }
    const double range = hi - lo;
    if (!(range > 1e-9))
        return Error{"the normal map is flat: there is no relief to make a height map of"};
    out.misfit = total > 0.0 ? std::sqrt(miss / total) : 0.0;
    out.heightScale = static_cast<float>(range);
    out.height = HeightField(W, H);
    for (std::size_t i = 0; i < N; ++i)
        out.height.texels[i] = static_cast<float>((f[i].real() - lo) / range);
    progress.finish();
    return out;
}

} // namespace px

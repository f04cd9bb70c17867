#pragma once
// Small helpers every test suite shares.

#include "parallax/heightfield/HeightField.h"
#include "parallax/trace/Tracer.h"

#include <cstddef>
#include <string>

namespace px::test {

// PX_TEST_SHARD=i/n: this process takes every n-th of a test's cases, from the i-th, so ctest runs
// one long test as n tests in parallel (and each within its time budget). Unset: all of them. A
// value that is not i/n with 0 <= i < n is a fatal error.
struct TestShard {
    std::size_t index = 0;
    std::size_t count = 1;
    bool takes(std::size_t i) const { return i % count == index; }
};
TestShard testShard();

// A file under PX_SHARED_DIR/testdata/ (third-party images, conformance tests only; see
// cmake/PxConformance.cmake).
std::string sharedTestData(const std::string& relative);

// Traces one ray; QFAILs (through the caller's QVERIFY) if the tracer cannot be created.
Result<Tracer> makeTracer(const HeightField& field, WrapMode wrap, Technique technique, float scale,
                          const TraceParams* params = nullptr);

// The hit of the ray uv(t) = uv0 + P t found by a dense march in double precision with bisection
// at every sign change: an oracle written independently of the kernels. `samples` steps over the
// whole [0, 1].
double denseMarchT(const HeightField& field, WrapMode wrap, double u0, double v0, double px,
                   double py, int samples);

// Bilinear height in double precision, wrap or clamp.
double bilinearHeight(const HeightField& field, WrapMode wrap, double u, double v);

} // namespace px::test

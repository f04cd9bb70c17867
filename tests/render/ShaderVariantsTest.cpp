// The uniforms and samplers a variant declares and GL reports active are exactly the ones its
// features need: a table written here from the features, independent of the generator, is compared
// with the generator's declarations for every variant, and with GL (llvmpipe on CI) for a covering
// set that links on the driver: every technique and output with every pair of values of two other
// features (211 programs, 3 % of the variants; linking all 7174 costs ~190 s of CPU, Mesa's link
// being the work). Every variant's text is compiled by core.shader.Glslang. PX_ALL_VARIANTS=1 links
// every one.

#include "RenderTestSupport.h"
#include "TestSupport.h"
#include "parallax/render/ShaderProgram.h"

#include <QtTest>
#include <algorithm>
#include <array>
#include <iterator>
#include <map>
#include <numeric>
#include <set>

using namespace px;

namespace {

std::set<std::string> needed(const VariantKey& k) {
    const TechniqueInfo& ti = info(k.technique);
    std::set<std::string> u;
    auto add = [&](std::initializer_list<const char*> names) {
        u.insert(names.begin(), names.end());
    };
    if (ti.parallax) {
        add({"pxHeightMap", "pxScale"});
        if (ti.usesLayers)
            add({"pxMinLayers", "pxMaxLayers", "pxHeightMax"});
        if (ti.usesBinarySteps || ti.usesSecantSteps)
            add({"pxRefineSteps"});
        if (ti.usesMaxSteps)
            add({"pxMaxSteps", "pxHeightMax"});
        if (ti.needsConeMap || ti.needsRelaxedConeMap)
            add({"pxConeMap"});
        if (ti.needsPyramid)
            add({"pxMaxMipAtlas", "pxMaxMipRows", "pxMaxMipTop"});
    }
    if (k.output == ShaderOutput::Trace) {
        add({"pxRayOrigins"});
        if (ti.parallax)
            add({"pxRayP"});
        return u;
    }
    add({"pxModel", "pxViewProjection"});
    // Texture coordinates: read by the trace, by every map, and by the surface output.
    const bool surface =
        k.output == ShaderOutput::Surface || k.output == ShaderOutput::FootprintSurface;
    if (ti.parallax || k.albedoMap || k.surfaceMap || k.normalSource != NormalSource::None ||
        surface)
        add({"pxTiling"});
    if (surface) {
        if (ti.parallax)
            add({"pxNormalMatrix", "pxCameraPos"});
        return u;
    }
    add({"pxNormalMatrix", "pxCameraPos", "pxLightDir", "pxLightColor", "pxBaseColor"});
    // An environment replaces the constant ambient and exposes the result.
    if (k.environment)
        add({"pxEnvSpecular", "pxSplitSum", "pxIrradianceSh", "pxEnvMaxLevel", "pxExposure"});
    else
        add({"pxAmbient"});
    if (k.lighting == LightingModel::BlinnPhong)
        add({"pxSpecular", "pxShininess"});
    else
        add({"pxRoughness", "pxMetallic"});
    if (k.albedoMap)
        add({"pxAlbedoMap"});
    if (k.surfaceMap)
        add({"pxOrmMap"});
    if (k.normalSource == NormalSource::Map)
        add({"pxNormalMap", "pxNormalGreenSign"});
    if (k.normalSource == NormalSource::HeightCentral ||
        k.normalSource == NormalSource::HeightSobel)
        add({"pxHeightMap", "pxScale"});
    if (k.shadow)
        add({"pxShadowSoftness", "pxMinLayers", "pxMaxLayers", "pxHeightMax"});
    return u;
}

// The features other than the technique and output, as small integers: what the covering set
// pairs up.
std::array<int, 9> features(const VariantKey& k) {
    return {k.shadow,
            static_cast<int>(k.normalSource),
            k.albedoMap,
            k.surfaceMap,
            k.wrap == WrapMode::Clamp,
            static_cast<int>(k.lighting),
            static_cast<int>(k.tbn),
            static_cast<int>(k.flavour),
            k.environment};
}

// A variant's technique and output (the two that shape the whole shader) with one pair of values
// of two other features: technique, output, feature i, its value, feature j, its value.
using FeaturePair = std::array<int, 6>;

std::vector<FeaturePair> pairsOf(const VariantKey& k) {
    const std::array<int, 9> f = features(k);
    std::vector<FeaturePair> pairs;
    for (int i = 0; i < 9; ++i) {
        for (int j = i + 1; j < 9; ++j)
            pairs.push_back(
                {static_cast<int>(k.technique), static_cast<int>(k.output), i, f[i], j, f[j]});
    }
    return pairs;
}

// Indices into `all` of variants such that every FeaturePair that occurs in some valid variant
// occurs in a chosen one (greedy: most pairs not yet covered first, ties to the lower index; a
// variant covers pairs of its own technique and output only, so each technique and output is
// covered on its own). Deterministic.
std::vector<std::size_t> coveringSet(const std::vector<VariantKey>& all) {
    std::map<std::pair<Technique, ShaderOutput>, std::vector<std::size_t>> groups;
    for (std::size_t i = 0; i < all.size(); ++i)
        groups[{all[i].technique, all[i].output}].push_back(i);
    std::vector<std::size_t> chosen;
    for (const auto& [group, indices] : groups) {
        std::set<FeaturePair> uncovered;
        for (std::size_t i : indices) {
            for (const FeaturePair& p : pairsOf(all[i]))
                uncovered.insert(p);
        }
        while (!uncovered.empty()) {
            std::size_t best = indices.front();
            int bestGain = 0;
            for (std::size_t i : indices) {
                int gain = 0;
                for (const FeaturePair& p : pairsOf(all[i]))
                    gain += static_cast<int>(uncovered.count(p));
                if (gain > bestGain) {
                    best = i;
                    bestGain = gain;
                }
            }
            for (const FeaturePair& p : pairsOf(all[best]))
                uncovered.erase(p);
            chosen.push_back(best);
        }
    }
    std::sort(chosen.begin(), chosen.end());
    return chosen;
}

std::string join(const std::set<std::string>& names) {
    std::string s;
    for (const std::string& n : names)
        s += (s.empty() ? "" : " ") + n;
    return s;
}

} // namespace

class ShaderVariantsTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() { QVERIFY(test::glContext()); }
    void everyVariantBuildsWithExactlyTheUniformsItNeeds();
    void theLinkedSetCoversEveryPairOfFeatures();
    void compileErrorsNameTheShaderFile();
};

void ShaderVariantsTest::everyVariantBuildsWithExactlyTheUniformsItNeeds() {
    QStringList failures;
    auto differ = [](const std::set<std::string>& got, const std::set<std::string>& want) {
        std::set<std::string> extra, missing;
        std::set_difference(got.begin(), got.end(), want.begin(), want.end(),
                            std::inserter(extra, extra.end()));
        std::set_difference(want.begin(), want.end(), got.begin(), got.end(),
                            std::inserter(missing, missing.end()));
        return "extra {" + join(extra) + "}, missing {" + join(missing) + "}";
    };
    const std::vector<VariantKey> all = allVariants();
    const bool linkAll = qEnvironmentVariableIntValue("PX_ALL_VARIANTS") == 1;
    std::vector<std::size_t> linked = coveringSet(all);
    if (linkAll) {
        linked.resize(all.size());
        std::iota(linked.begin(), linked.end(), std::size_t{0});
    }
    // ctest runs the shards in parallel (TestSupport.h): each generates its share of every
    // variant and links its share of the linked ones.
    const test::TestShard shard = test::testShard();
    std::size_t next = 0; // the next entry of `linked` not yet reached
    int generatedCount = 0, built = 0, expectedBuilt = 0;
    for (std::size_t i = 0; i < all.size(); ++i) {
        const bool link = next < linked.size() && linked[next] == i;
        next += link ? 1 : 0;
        if (!shard.takes(i))
            continue;
        expectedBuilt += link ? 1 : 0;
        const VariantKey& k = all[i];
        Result<GeneratedProgram> generated = generateProgram(k);
        QVERIFY2(generated.ok(), k.name().c_str());
        ++generatedCount;
        std::set<std::string> declared;
        for (const GeneratedShader* s : {&generated->vertex, &generated->fragment}) {
            for (const ShaderUniform& u : s->uniforms)
                declared.insert(u.name);
        }
        const std::set<std::string> expected = needed(k);
        if (declared != expected)
            failures << QString::fromStdString(k.name() + ": the generator declares " +
                                               differ(declared, expected));
        if (!link)
            continue;
        Result<ShaderProgram> program = ShaderProgram::build(*generated);
        QVERIFY2(program.ok(), program ? "" : program.error().message.c_str());
        const std::vector<std::string> active = program->activeUniforms();
        const std::set<std::string> gl(active.begin(), active.end());
        if (gl != expected)
            failures << QString::fromStdString(k.name() + ": GL reports " + differ(gl, expected));
        ++built;
    }
    QVERIFY2(failures.isEmpty(),
             qPrintable(QString("%1 problems, the first:\n").arg(failures.size()) +
                        failures.mid(0, 40).join("\n")));
    QCOMPARE(next, linked.size());
    QCOMPARE(built, expectedBuilt);
    QVERIFY(built > 0 && (linkAll ? generatedCount == built : generatedCount > built));
    qInfo("%d variants generated, %d linked on the driver (%zu of %zu in all shards)",
          generatedCount, built, linked.size(), all.size());
}

// The covering set holds, for every technique and output, every pair of two other features' values
// that occurs: the test can fail on any two features interacting in one technique's shader, at a
// fraction of the cost of linking everything.
void ShaderVariantsTest::theLinkedSetCoversEveryPairOfFeatures() {
    const std::vector<VariantKey> all = allVariants();
    const std::vector<std::size_t> linked = coveringSet(all);
    std::set<FeaturePair> wanted, got;
    for (std::size_t n = 0; n < all.size(); ++n) {
        const bool chosen = std::binary_search(linked.begin(), linked.end(), n);
        for (const FeaturePair& p : pairsOf(all[n])) {
            wanted.insert(p);
            if (chosen)
                got.insert(p);
        }
    }
    QCOMPARE(got.size(), wanted.size());
    QVERIFY2(linked.size() * 10 < all.size(), qPrintable(QString::number(linked.size())));
}

// A compiler error in a generated shader is reported against the file in shaders/ it came from.
void ShaderVariantsTest::compileErrorsNameTheShaderFile() {
    Result<GeneratedProgram> generated = generateProgram(VariantKey{});
    QVERIFY(generated.ok());
    GeneratedProgram broken = *generated;
    std::string& text = broken.fragment.text;
    const std::size_t at = text.find("float pxTracePom(vec2 uv0, vec2 P) {\n");
    QVERIFY(at != std::string::npos);
    text.insert(text.find('\n', at) + 1, "    undeclaredThing += 1;\n");
    Result<ShaderProgram> program = ShaderProgram::build(broken);
    QVERIFY(!program.ok());
    const std::string& message = program.error().message;
    QVERIFY2(message.find("shaders/trace/pom.glsl:") != std::string::npos, message.c_str());
    QVERIFY2(message.find("undeclaredThing") != std::string::npos, message.c_str());
}

QTEST_APPLESS_MAIN(ShaderVariantsTest)
#include "ShaderVariantsTest.moc"

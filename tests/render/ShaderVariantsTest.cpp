// Every variant compiles and links on the driver (llvmpipe on CI), and the uniforms and samplers
// GL reports active are exactly the ones its features need: a table written here from the
// features, independent of the generator, is compared with both GL and the generator.

#include "RenderTestSupport.h"
#include "TestSupport.h"
#include "parallax/render/ShaderProgram.h"

#include <QtTest>
#include <algorithm>
#include <iterator>
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
    if (ti.parallax || k.albedoMap || k.surfaceMap || k.normalSource != NormalSource::None ||
        k.output == ShaderOutput::Surface)
        add({"pxTiling"});
    if (k.output == ShaderOutput::Surface) {
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
    void compileErrorsNameTheShaderFile();
};

void ShaderVariantsTest::everyVariantBuildsWithExactlyTheUniformsItNeeds() {
    int built = 0;
    QStringList failures;
    auto differ = [](const std::set<std::string>& got, const std::set<std::string>& want) {
        std::set<std::string> extra, missing;
        std::set_difference(got.begin(), got.end(), want.begin(), want.end(),
                            std::inserter(extra, extra.end()));
        std::set_difference(want.begin(), want.end(), got.begin(), got.end(),
                            std::inserter(missing, missing.end()));
        return "extra {" + join(extra) + "}, missing {" + join(missing) + "}";
    };
    // ctest runs the shards in parallel (TestSupport.h).
    const test::TestShard shard = test::testShard();
    const std::vector<VariantKey> all = allVariants();
    int expectedCount = 0;
    for (std::size_t i = 0; i < all.size(); ++i) {
        if (!shard.takes(i))
            continue;
        ++expectedCount;
        const VariantKey& k = all[i];
        Result<GeneratedProgram> generated = generateProgram(k);
        QVERIFY2(generated.ok(), k.name().c_str());
        Result<ShaderProgram> program = ShaderProgram::build(*generated);
        QVERIFY2(program.ok(), program ? "" : program.error().message.c_str());
        const std::vector<std::string> active = program->activeUniforms();
        const std::set<std::string> gl(active.begin(), active.end());
        std::set<std::string> declared;
        for (const GeneratedShader* s : {&generated->vertex, &generated->fragment}) {
            for (const ShaderUniform& u : s->uniforms)
                declared.insert(u.name);
        }
        const std::set<std::string> expected = needed(k);
        if (gl != expected)
            failures << QString::fromStdString(k.name() + ": GL reports " + differ(gl, expected));
        if (declared != expected)
            failures << QString::fromStdString(k.name() + ": the generator declares " +
                                               differ(declared, expected));
        ++built;
    }
    QVERIFY2(failures.isEmpty(),
             qPrintable(QString("%1 problems, the first:\n").arg(failures.size()) +
                        failures.mid(0, 40).join("\n")));
    QCOMPARE(built, expectedCount);
    QVERIFY(built > 0);
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

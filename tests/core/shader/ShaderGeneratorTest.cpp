// The generator: each variant carries only the code, samplers and uniforms its features use,
// defines only for bits that are on, and #line directives that point at the right file lines.

#include "parallax/shader/ShaderGenerator.h"

#include "TestSupport.h"

#include <QtTest>
#include <cctype>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>

using namespace px;

namespace {

// The generated code without comments (line and block), so words in comments do not count as
// code.
std::string code(const std::string& text) {
    std::string out;
    out.reserve(text.size());
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (text[i] != '/') {
            out += text[i];
            continue;
        }
        if (text.compare(i, 2, "//") == 0) {
            while (i < text.size() && text[i] != '\n')
                ++i;
        } else if (text.compare(i, 2, "/*") == 0) {
            const std::size_t end = text.find("*/", i + 2);
            i = end == std::string::npos ? text.size() : end + 2;
            out += ' ';
        }
        if (i < text.size())
            out += text[i];
    }
    return out;
}

bool isWordChar(char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
}

int countWord(const std::string& text, const std::string& word) {
    int n = 0;
    for (std::size_t at = text.find(word); at != std::string::npos; at = text.find(word, at + 1)) {
        const bool before = at > 0 && isWordChar(text[at - 1]);
        const bool after = at + word.size() < text.size() && isWordChar(text[at + word.size()]);
        n += !before && !after;
    }
    return n;
}

bool hasWord(const std::string& text, const std::string& word) {
    return countWord(text, word) > 0;
}

// `code` (comments stripped) without its uniform declarations: what is left reads the uniforms.
std::string withoutDeclarations(std::string code) {
    for (std::size_t at = code.find("uniform"); at != std::string::npos;
         at = code.find("uniform", at + 1)) {
        const bool word = (at == 0 || !isWordChar(code[at - 1])) &&
                          (at + 7 == code.size() || !isWordChar(code[at + 7]));
        const std::size_t end = code.find(';', at);
        if (word && end != std::string::npos)
            code.replace(at, end + 1 - at, " ");
    }
    return code;
}

bool hasLoop(const std::string& text) {
    return hasWord(text, "for") || hasWord(text, "while") || hasWord(text, "do");
}

std::vector<std::string> fileLines(const std::string& relative) {
    std::ifstream in(std::string(PX_SOURCE_DIR) + "/" + relative);
    std::vector<std::string> lines;
    for (std::string line; std::getline(in, line);)
        lines.push_back(line);
    return lines;
}

std::string techniqueMacro(Technique t) {
    std::string m = "PX_TECHNIQUE_";
    for (char c : info(t).name)
        m += c == '-' ? '_' : static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return m;
}

GeneratedProgram generate(const VariantKey& key) {
    Result<GeneratedProgram> p = generateProgram(key);
    if (!p)
        qFatal("%s: %s", key.name().c_str(), p.error().message.c_str());
    return std::move(*p);
}

VariantKey keyOf(Technique technique, NormalSource normals = NormalSource::HeightCentral) {
    VariantKey k;
    k.technique = technique;
    k.normalSource = normals;
    return k;
}

} // namespace

class ShaderGeneratorTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void definesOnlyForBitsThatAreOn();
    void normalMappingHasNoLoopAndNoConeSampler();
    void onlyConeTechniquesReadTheConeMap();
    void shadowCodeOnlyWithShadow();
    void everyDeclaredUniformIsRead();
    void lineDirectivesPointAtTheirFiles();
    void compilerLogsNameTheFile();
    void invalidKeysAreRefused();
    void productionKernelsSampleInHardware();
    void vertexStagesAreKeyedByWhatTheyRead();

private:
    test::TestShard m_shard;
    std::vector<GeneratedProgram> m_all; // every variant of the shard, generated once
};

void ShaderGeneratorTest::initTestCase() {
    // ctest runs the shards in parallel (TestSupport.h); each check looks at its shard's variants.
    m_shard = test::testShard();
    const std::vector<VariantKey> all = allVariants();
    for (std::size_t i = m_shard.index; i < all.size(); i += m_shard.count)
        m_all.push_back(generate(all[i]));
    QVERIFY(!m_all.empty());
}

void ShaderGeneratorTest::definesOnlyForBitsThatAreOn() {
    for (const GeneratedProgram& p : m_all) {
        const VariantKey& k = p.key;
        const std::string& t = p.fragment.text;
        auto defined = [&](const char* name) {
            return t.find(std::string("#define ") + name + " 1\n") != std::string::npos;
        };
        const std::string name = k.name();
        QVERIFY2(defined(techniqueMacro(k.technique).c_str()), name.c_str());
        QCOMPARE(defined("PX_HAS_SHADOW"), k.shadow);
        QCOMPARE(defined("PX_HAS_NORMAL_MAP"), k.normalSource == NormalSource::Map);
        QCOMPARE(defined("PX_HAS_SOBEL_NORMALS"), k.normalSource == NormalSource::HeightSobel);
        QCOMPARE(defined("PX_HAS_ALBEDO_MAP"), k.albedoMap);
        QCOMPARE(defined("PX_HAS_SURFACE_MAP"), k.surfaceMap);
        QCOMPARE(defined("PX_HAS_CLAMP_WRAP"), k.wrap == WrapMode::Clamp);
        QCOMPARE(defined("PX_HAS_METALLIC_ROUGHNESS"),
                 k.lighting == LightingModel::MetallicRoughness);
        QCOMPARE(defined("PX_HAS_DERIVATIVE_TBN"), k.tbn == TbnSource::Derivatives);
        QCOMPARE(defined("PX_HAS_PARALLAX"), info(k.technique).parallax);
        QCOMPARE(defined("PX_HAS_TRACE_OUTPUT"), k.output == ShaderOutput::Trace);
        // One technique define, and no define that is off.
        QCOMPARE(std::count(p.fragment.defines.begin(), p.fragment.defines.end(), std::string()),
                 0);
        const std::size_t techniques =
            std::count_if(p.fragment.defines.begin(), p.fragment.defines.end(),
                          [](const std::string& d) { return d.rfind("PX_TECHNIQUE_", 0) == 0; });
        QCOMPARE(techniques, std::size_t(1));
    }
}

void ShaderGeneratorTest::normalMappingHasNoLoopAndNoConeSampler() {
    for (NormalSource source :
         {NormalSource::Map, NormalSource::HeightCentral, NormalSource::HeightSobel}) {
        const GeneratedProgram p = generate(keyOf(Technique::Normal, source));
        const std::string c = code(p.fragment.text);
        QVERIFY(!hasLoop(c));
        QVERIFY(!hasWord(c, "pxConeMap") && !hasWord(c, "pxMaxMipAtlas"));
        QVERIFY(!hasWord(c, "pxMinLayers") && !hasWord(c, "pxMaxSteps"));
        QCOMPARE(hasWord(c, "pxHeightMap"), source != NormalSource::Map);
        QCOMPARE(hasWord(c, "pxNormalMap"), source == NormalSource::Map);
    }
    const std::string none = code(generate(keyOf(Technique::None)).fragment.text);
    QVERIFY(!hasLoop(none) && !hasWord(none, "pxHeightMap"));
    // Offset parallax is one fetch: no loop either.
    QVERIFY(!hasLoop(code(generate(keyOf(Technique::Offset)).fragment.text)));
    QVERIFY(hasLoop(code(generate(keyOf(Technique::Pom)).fragment.text)));
}

void ShaderGeneratorTest::onlyConeTechniquesReadTheConeMap() {
    for (const GeneratedProgram& p : m_all) {
        const VariantKey& k = p.key;
        const std::string c = code(p.fragment.text);
        const bool cone = k.technique == Technique::Cone || k.technique == Technique::RelaxedCone;
        QVERIFY2(hasWord(c, "pxConeMap") == cone, k.name().c_str());
        QVERIFY2(hasWord(c, "pxMaxMipAtlas") == (k.technique == Technique::Pyramid),
                 k.name().c_str());
        QVERIFY2(hasWord(c, "pxMinLayers") == (info(k.technique).usesLayers || k.shadow),
                 k.name().c_str());
    }
}

void ShaderGeneratorTest::shadowCodeOnlyWithShadow() {
    int withShadow = 0;
    for (const GeneratedProgram& p : m_all) {
        const VariantKey& k = p.key;
        const std::string c = code(p.fragment.text);
        QVERIFY2(hasWord(c, "pxSoftShadow") == k.shadow, k.name().c_str());
        QVERIFY2(hasWord(c, "pxShadowSoftness") == k.shadow, k.name().c_str());
        withShadow += k.shadow;
    }
    QVERIFY(withShadow > 0);
}

void ShaderGeneratorTest::everyDeclaredUniformIsRead() {
    // The check itself: a declaration, a comment or a second declaration is no read.
    const std::string declared = "uniform float pxA; // pxA\n/* pxA */ uniform float pxB, pxA;\n";
    QVERIFY(!hasWord(withoutDeclarations(code(declared + "void main() { x = pxB; }")), "pxA"));
    QVERIFY(hasWord(withoutDeclarations(code(declared + "void main() { x = pxA; }")), "pxA"));
    for (const GeneratedProgram& p : m_all) {
        const VariantKey& k = p.key;
        for (const GeneratedShader* s : {&p.vertex, &p.fragment}) {
            const std::string reads = withoutDeclarations(code(s->text));
            for (const ShaderUniform& u : s->uniforms)
                QVERIFY2(hasWord(reads, u.name),
                         (k.name() + ": " + u.name + " declared, never read").c_str());
            // And every px uniform the code names is declared (else it would not compile).
            QVERIFY(s->text.rfind("#version 430 core\n", 0) == 0);
        }
    }
}

void ShaderGeneratorTest::lineDirectivesPointAtTheirFiles() {
    std::map<std::string, std::vector<std::string>> files;
    int checked = 0;
    for (const VariantKey& k :
         {keyOf(Technique::Pyramid), keyOf(Technique::Relief, NormalSource::HeightSobel),
          keyOf(Technique::Normal, NormalSource::Map)}) {
        const GeneratedProgram p = generate(k);
        for (const GeneratedShader* s : {&p.vertex, &p.fragment}) {
            std::istringstream in(s->text);
            int source = -1;
            int line = 0;
            static const std::regex directive(R"(#line (\d+) (\d+))");
            for (std::string out; std::getline(in, out);) {
                std::smatch m;
                if (std::regex_match(out, m, directive)) {
                    source = std::stoi(m[2]);
                    line = std::stoi(m[1]) - 10000 * source;
                    continue;
                }
                if (source <= 0) {
                    continue; // the generated header
                }
                const std::string& path = s->sources.at(static_cast<std::size_t>(source));
                if (!files.count(path))
                    files[path] = fileLines(path);
                const std::vector<std::string>& lines = files[path];
                QVERIFY2(line >= 1 && line <= static_cast<int>(lines.size()), path.c_str());
                const std::string& original = lines[static_cast<std::size_t>(line - 1)];
                // Lines are verbatim; #if lines and the branches not taken become blank lines.
                const bool same = out == original || out.empty();
                QVERIFY2(same, (path + ":" + std::to_string(line) + ": generated \"" + out +
                                "\" is \"" + original + "\" there")
                                   .c_str());
                checked += !out.empty();
                ++line;
            }
        }
    }
    QVERIFY(checked > 300);
}

void ShaderGeneratorTest::compilerLogsNameTheFile() {
    const std::vector<std::string> sources{"(generated header)", "shaders/render/bindings.glsl",
                                           "shaders/trace/pom.glsl"};
    QCOMPARE(mapCompilerLog("2:12(5): error: `x' undeclared", sources),
             std::string("shaders/trace/pom.glsl:12(5): error: `x' undeclared"));
    QCOMPARE(mapCompilerLog("ERROR: 1:7: 'y' : undeclared identifier", sources),
             std::string("ERROR: shaders/render/bindings.glsl:7: 'y' : undeclared identifier"));
    QCOMPARE(mapCompilerLog("2(30) : error C1008: undefined variable", sources),
             std::string("shaders/trace/pom.glsl:30 : error C1008: undefined variable"));
    // Source numbers the program does not have, and plain numbers, are left alone.
    QCOMPARE(mapCompilerLog("9:3(1): error; 1.5:2", sources), std::string("9:3(1): error; 1.5:2"));
    // Mesa reports source 0 whatever #line says: the line number carries the source.
    QCOMPARE(mapCompilerLog("0:20012(2): error: `foo' undeclared", sources),
             std::string("shaders/trace/pom.glsl:12(2): error: `foo' undeclared"));
    QCOMPARE(mapCompilerLog("0:5(2): error", sources),
             std::string("(generated header):5(2): error"));
    // Numbers too long for any integer type: left as they are, nothing thrown.
    const std::string huge = "0:123456789012345678901234567890(2): error; 98765432109876543210:4";
    QCOMPARE(mapCompilerLog(huge, sources), huge);
    QCOMPARE(mapCompilerLog("2:99999999999999999999999999(7): x", sources),
             std::string("2:99999999999999999999999999(7): x"));
}

void ShaderGeneratorTest::invalidKeysAreRefused() {
    Result<GeneratedProgram> p = generateProgram(keyOf(Technique::Normal, NormalSource::None));
    QVERIFY(!p.ok());
    QVERIFY(p.error().message.find("normal source") != std::string::npos);
}

// Production: the texture units filter (textureGrad, textureLod on the cone map, textureGather
// for a cell's corners), no texelFetch of height or cones, no `precise`, and no fetch counter in
// the colour output, which writes none. Verify: texel reads filtered in code, `precise` kept.
void ShaderGeneratorTest::productionKernelsSampleInHardware() {
    int production = 0, verify = 0;
    for (const GeneratedProgram& p : m_all) {
        const VariantKey& k = p.key;
        const std::string c = code(p.fragment.text);
        const std::string name = k.name();
        const bool hardware = c.find("#define PX_HAS_HARDWARE_SAMPLING 1") != std::string::npos;
        QVERIFY2(hardware == (k.flavour == KernelFlavour::Production && k.readsHeightMap()),
                 name.c_str());
        QVERIFY2(!hasWord(c, "pxHeightTexel") || !hardware, name.c_str());
        QVERIFY2(!hasWord(c, "pxConeTexel") || !hardware, name.c_str());
        const bool cells = k.technique == Technique::Cone ||
                           k.technique == Technique::RelaxedCone ||
                           k.technique == Technique::Pyramid || k.technique == Technique::Exact;
        if (k.flavour == KernelFlavour::Verify) {
            QVERIFY2(k.readsHeightMap(), name.c_str()); // canonical() folds the others
            QVERIFY2(hasWord(c, "pxHeightTexel"), name.c_str());
            QVERIFY2(!hasWord(c, "textureGrad") || k.albedoMap || k.surfaceMap ||
                         k.normalSource == NormalSource::Map,
                     name.c_str());
            QVERIFY2(hasWord(c, "pxFetches"), name.c_str());
            ++verify;
            continue;
        }
        QVERIFY2(!hasWord(c, "precise"), name.c_str());
        QVERIFY2(hasWord(c, "pxFetches") == (k.output != ShaderOutput::Color && hardware),
                 name.c_str());
        if (hardware && info(k.technique).parallax) {
            // Cell walks gather corners; marches filter samples.
            QVERIFY2(hasWord(c, "textureGather") == cells, name.c_str());
            QVERIFY2(hasWord(c, "pxHeightFiltered") || cells, name.c_str());
            ++production;
        }
    }
    // Over 1000 of each in all (a shard holds every count-th variant).
    QVERIFY(production * m_shard.count > 1000);
    QVERIFY(verify * m_shard.count > 1000);
    // Every height-reading variant exists in both flavours.
    VariantKey k = keyOf(Technique::Cone);
    k.flavour = KernelFlavour::Verify;
    QVERIFY(canonical(k).flavour == KernelFlavour::Verify);
    k.technique = Technique::None;
    k.normalSource = NormalSource::Map;
    QVERIFY(canonical(k).flavour == KernelFlavour::Production); // reads no height: one flavour
}

// The vertex stage reads only which outputs the fragment stage keeps: every program with the
// same vertex key has the same vertex text, different keys have different texts, and the few
// distinct stages are what `shader --dump-all` writes once each.
void ShaderGeneratorTest::vertexStagesAreKeyedByWhatTheyRead() {
    // The trace pass, and four mesh stages: uv only (the surface output of none/normal), position
    // and normal (colour without a texture), + uv (maps, polygon frame), + tangent and bitangent
    // (parallax and normals with the vertex frame; derivative frames read no tangents).
    const std::set<std::string> expected{"trace", "mesh+vUv", "mesh+vNormal+vPosition",
                                         "mesh+vNormal+vPosition+vUv",
                                         "mesh+vBitangent+vNormal+vPosition+vTangent+vUv"};
    std::map<VertexKey, std::string> stages;
    auto check = [&](const GeneratedProgram& p) {
        auto [it, added] = stages.emplace(p.vertexKey, p.vertex.text);
        QVERIFY2(added || it->second == p.vertex.text,
                 (p.key.name() + ": vertex stage " + p.vertexKey.name() + " differs").c_str());
        QVERIFY2(expected.contains(p.vertexKey.name()),
                 (p.key.name() + ": vertex stage " + p.vertexKey.name()).c_str());
        QVERIFY2(p.vertex.text.find(p.vertexKey.name()) != std::string::npos, p.key.name().c_str());
        // No feature define of the program reaches the vertex stage.
        for (const std::string& d : p.vertex.defines)
            QVERIFY2(d.rfind("PX_FRAGMENT_READS_", 0) == 0, d.c_str());
    };
    for (const GeneratedProgram& p : m_all) {
        check(p);
        if (QTest::currentTestFailed())
            return;
    }
    qInfo("%zu distinct vertex stages for %zu programs", stages.size(), m_all.size());
    // A shard need not hold every stage: the other shards' variants, until each has been seen.
    const std::vector<VariantKey> all = allVariants();
    for (std::size_t i = 0; i < all.size() && stages.size() < expected.size(); ++i) {
        if (!m_shard.takes(i))
            check(generate(all[i]));
        if (QTest::currentTestFailed())
            return;
    }
    std::set<std::string> texts, names;
    for (const auto& [key, text] : stages) {
        texts.insert(text);
        names.insert(key.name());
    }
    QCOMPARE(texts.size(), stages.size());
    QVERIFY(names == expected);
}

QTEST_APPLESS_MAIN(ShaderGeneratorTest)
#include "ShaderGeneratorTest.moc"

// Variant keys: bits round-trip, validity, the canonicalising filter and the variant count.

#include "parallax/shader/VariantKey.h"

#include <QtTest>
#include <set>

using namespace px;

class VariantKeyTest : public QObject {
    Q_OBJECT

private slots:
    void bitsRoundTrip();
    void outOfRangeBitsAreRejected();
    void flavourNamesRoundTrip();
    void canonicalIsIdempotentAndValidityPreserving();
    void variantCount();
    void canonicalDropsWhatIsNeverRead();
    void normalTechniqueNeedsANormalSource();
    void namesAreUnique();
    void materialDecidesTheKey();
};

void VariantKeyTest::bitsRoundTrip() {
    int decoded = 0;
    for (std::uint32_t b = 0; b < kVariantKeyCount; ++b) {
        if (const std::optional<VariantKey> k = VariantKey::fromBits(b)) {
            QCOMPARE(k->bits(), b);
            ++decoded;
        }
    }
    // 11 techniques of 16 codes, every output code (4) used.
    QCOMPARE(decoded, static_cast<int>(kVariantKeyCount) / 16 * 11);
}

void VariantKeyTest::outOfRangeBitsAreRejected() {
    QVERIFY(!VariantKey::fromBits(11).has_value());               // technique code 11
    QVERIFY(!VariantKey::fromBits(15u | (3u << 12)).has_value()); // technique code 15
    QVERIFY(!VariantKey::fromBits(kVariantKeyCount).has_value());
}

void VariantKeyTest::flavourNamesRoundTrip() {
    for (KernelFlavour f : {KernelFlavour::Production, KernelFlavour::Verify})
        QVERIFY(shader::parseKernelFlavour(shader::kernelFlavourName(f)) == f);
    QVERIFY(!shader::parseKernelFlavour("fast").has_value());
    VariantKey k;
    k.flavour = KernelFlavour::Verify;
    QCOMPARE(QString::fromStdString(k.name()), QString("pom+central+verify"));
    QVERIFY(VariantKey::fromBits(k.bits()) == k);
}

void VariantKeyTest::canonicalIsIdempotentAndValidityPreserving() {
    for (std::uint32_t b = 0; b < kVariantKeyCount; ++b) {
        const std::optional<VariantKey> k = VariantKey::fromBits(b);
        if (!k || !k->isValid())
            continue;
        const VariantKey c = canonical(*k);
        QVERIFY2(c.isValid(), qPrintable(QString::fromStdString(k->name())));
        QVERIFY(canonical(c) == c);
        QVERIFY(c.technique == k->technique ||
                c.technique == Technique::None); // a hit no one reads
        // The footprint reference is exact's: any other technique's draws as Surface.
        QVERIFY(c.output == k->output ||
                (k->output == ShaderOutput::FootprintSurface && c.output == ShaderOutput::Surface &&
                 k->technique != Technique::Exact));
    }
}

void VariantKeyTest::variantCount() {
    // Colour: none 2*2*2*2 (albedo, orm, lighting, tbn); normal (map + 2 height filters x 2 wraps)
    // x 16; 9 parallax techniques x shadow 2 x normal source 4 x 16 x wrap 2, less the 4 (lighting
    // x tbn) of each whose hit nothing reads. Surface: 9 x wrap 2 x tbn 2 + 2 x tbn 2. Trace:
    // 9 x wrap 2 + 2.
    const std::size_t colour = 16 + 5 * 16 + 9 * (2 * 4 * 16 * 2 - 4);
    const std::size_t production = colour + (9 * 2 * 2 + 2 * 2) + (9 * 2 + 2);
    // Verify kernels for every variant that reads the height map: all but colour none (16),
    // normal from a normal map (16), and none/normal in the surface (2 x tbn 2) and trace outputs.
    // Plus exact's footprint reference (wrap 2 x tbn 2), verify kernels only.
    const std::size_t verify = production - (16 + 16 + 4 + 2) + 2 * 2;
    // Under an environment: every colour variant once more, production kernels only.
    const std::size_t environment = colour;
    const std::size_t expected = production + verify + environment;
    const std::vector<VariantKey> all = allVariants();
    QCOMPARE(all.size(), expected);
    for (const VariantKey& k : all) {
        QVERIFY(k.isValid());
        QVERIFY(canonical(k) == k);
    }
}

void VariantKeyTest::canonicalDropsWhatIsNeverRead() {
    VariantKey lit;
    lit.environment = true;
    lit.flavour = KernelFlavour::Verify;
    QVERIFY(canonical(lit).environment);
    QVERIFY(canonical(lit).flavour == KernelFlavour::Production); // verify serves hit data only
    lit.output = ShaderOutput::Surface;
    QVERIFY(!canonical(lit).environment); // nothing is lit in the hit data
    QCOMPARE(canonical(lit).flavour, KernelFlavour::Verify);

    // The reference on the footprint's level: exact alone, in the verify kernels.
    VariantKey footprint;
    footprint.output = ShaderOutput::FootprintSurface;
    QVERIFY(canonical(footprint).output == ShaderOutput::Surface); // pom reads that level anyway
    footprint.technique = Technique::Exact;
    QVERIFY(canonical(footprint).output == ShaderOutput::FootprintSurface);
    QCOMPARE(canonical(footprint).flavour, KernelFlavour::Verify);
    QCOMPARE(QString::fromStdString(canonical(footprint).name()),
             QString("exact+footprint-surface+verify"));

    VariantKey k;
    k.technique = Technique::None;
    k.shadow = true;
    k.normalSource = NormalSource::HeightSobel;
    k.wrap = WrapMode::Clamp;
    VariantKey c = canonical(k);
    QVERIFY(!c.shadow);
    QVERIFY(c.normalSource == NormalSource::None);
    QVERIFY(c.wrap == WrapMode::Repeat); // nothing reads the height map

    k.technique = Technique::Normal;
    k.normalSource = NormalSource::Map;
    c = canonical(k);
    QVERIFY(!c.shadow);
    QVERIFY(c.wrap == WrapMode::Repeat);
    k.normalSource = NormalSource::HeightCentral;
    QVERIFY(canonical(k).wrap == WrapMode::Clamp); // derived normals read heights with the wrap

    k.technique = Technique::Pom;
    k.albedoMap = true;
    k.lighting = LightingModel::MetallicRoughness;
    k.output = ShaderOutput::Trace;
    k.tbn = TbnSource::Derivatives;
    c = canonical(k);
    QVERIFY(!c.shadow && !c.albedoMap);
    QVERIFY(c.normalSource == NormalSource::None);
    QVERIFY(c.lighting == LightingModel::BlinnPhong);
    QVERIFY(c.tbn == TbnSource::VertexTangents);
    QVERIFY(c.wrap == WrapMode::Clamp);
    k.output = ShaderOutput::Surface;
    QVERIFY(canonical(k).tbn == TbnSource::Derivatives); // a mesh: its frame matters
    k.output = ShaderOutput::Color;
    QVERIFY(canonical(k).shadow);

    // A parallax hit that nothing reads: no map, polygon normals, no shadow, no clamp discard.
    VariantKey blind;
    blind.technique = Technique::Relief;
    blind.normalSource = NormalSource::None;
    QVERIFY(canonical(blind).technique == Technique::None);
    blind.wrap = WrapMode::Clamp; // the hit decides the silhouette
    QVERIFY(canonical(blind).technique == Technique::Relief);
}

void VariantKeyTest::normalTechniqueNeedsANormalSource() {
    VariantKey k;
    k.technique = Technique::Normal;
    k.normalSource = NormalSource::None;
    QVERIFY(!k.isValid());
    QVERIFY(k.validate().error().message.find("normal source") != std::string::npos);
    k.output = ShaderOutput::Trace;
    QVERIFY(k.isValid());
}

void VariantKeyTest::namesAreUnique() {
    std::set<std::string> names;
    for (const VariantKey& k : allVariants())
        QVERIFY2(names.insert(k.name()).second, k.name().c_str());
}

void VariantKeyTest::materialDecidesTheKey() {
    Material m;
    m.technique = Technique::Cone;
    m.selfShadow = true;
    m.normalSource = NormalSource::Map;
    m.maps.height = "h.png";
    m.maps.albedo = "a.png";
    m.maps.roughness = "r.png";
    m.wrap = WrapMode::Clamp;
    m.lighting = LightingModel::MetallicRoughness;
    VariantKey k = variantFor(m);
    QVERIFY(k.technique == Technique::Cone);
    QVERIFY(k.shadow && k.albedoMap && k.surfaceMap);
    QVERIFY(k.normalSource == NormalSource::HeightCentral); // no normal map file: derived
    QVERIFY(k.wrap == WrapMode::Clamp);
    QVERIFY(k.lighting == LightingModel::MetallicRoughness);
    m.maps.normal = "n.png";
    QVERIFY(variantFor(m).normalSource == NormalSource::Map);
    m.maps.albedo.clear();
    m.maps.roughness.clear();
    k = variantFor(m);
    QVERIFY(!k.albedoMap && !k.surfaceMap);
}

QTEST_APPLESS_MAIN(VariantKeyTest)
#include "VariantKeyTest.moc"

// Every convention the importer claims (docs/texture-sets.md), each as a set the test writes with
// known truth, over seeds that vary the relief and, where the name does not say it, the normal
// map's green: the material must name the right file for each map, read the right channel, tell
// height from depth and the green from the data, and hold the written height texel for texel.

#include "ConventionSets.h"
#include "parallax/io/AtomicWrite.h"
#include "parallax/material/TextureSetImport.h"

#include <QTemporaryDir>
#include <QtTest>
#include <cmath>
#include <optional>

using namespace px;
using namespace px::test;

namespace {

struct Channel {
    std::string file; // "" : none
    HeightChannel channel = HeightChannel::Red;
    bool gloss = false;
};

struct Convention {
    std::string name;
    std::vector<ConventionFile> files; // "{s}" stands for the set's name
    std::optional<NormalGreen> green;  // fixed by the names; else varied by seed
    std::string height;                // the file holding the height; "" : none
    HeightChannel heightChannel = HeightChannel::Red;
    bool depth = false;
    std::string normal, albedo;
    Channel roughness, ao, metallic;
    std::string specular = {}; // kept for the engines that read one
};

std::string named(const std::string& pattern, const std::string& stem) {
    std::string out = pattern;
    for (std::size_t at; (at = out.find("{s}")) != std::string::npos;)
        out.replace(at, 3, stem);
    return out;
}

std::vector<Convention> conventions() {
    using T = Texels;
    const auto gl = NormalGreen::OpenGL, dx = NormalGreen::DirectX;
    const auto R = HeightChannel::Red, G = HeightChannel::Green, B = HeightChannel::Blue,
               A = HeightChannel::Alpha;
    std::vector<Convention> c;
    c.push_back({"poly-haven",
                 {{"{s}_diff_1k.jpg", T::Albedo},
                  {"{s}_nor_gl_1k.png", T::Normal},
                  {"{s}_nor_dx_1k.png", T::Normal},
                  {"{s}_disp_1k.png", T::Height},
                  {"{s}_arm_1k.png", T::Packed},
                  {"{s}_rough_1k.jpg", T::Grey},
                  {"{s}_spec_1k.png", T::Grey}},
                 gl,
                 "{s}_disp_1k.png",
                 R,
                 false,
                 "{s}_nor_gl_1k.png",
                 "{s}_diff_1k.jpg",
                 {"{s}_rough_1k.jpg", R},
                 {"{s}_arm_1k.png", R},
                 {"{s}_arm_1k.png", B}});
    c.back().specular = "{s}_spec_1k.png";
    c.push_back({"ambientcg",
                 {{"{s}_1K-PNG_Color.png", T::Albedo},
                  {"{s}_1K-PNG_NormalGL.png", T::Normal},
                  {"{s}_1K-PNG_Displacement.png", T::Height},
                  {"{s}_1K-PNG_Roughness.png", T::Grey},
                  {"{s}_1K-PNG_AmbientOcclusion.png", T::Grey},
                  {"{s}_1K-PNG.png", T::Albedo}},
                 gl,
                 "{s}_1K-PNG_Displacement.png",
                 R,
                 false,
                 "{s}_1K-PNG_NormalGL.png",
                 "{s}_1K-PNG_Color.png",
                 {"{s}_1K-PNG_Roughness.png", R},
                 {"{s}_1K-PNG_AmbientOcclusion.png", R},
                 {}});
    c.push_back({"ambientcg-directx-depth",
                 {{"{s}_1K-PNG_Color.png", T::Albedo},
                  {"{s}_1K-PNG_NormalDX.png", T::Normal},
                  {"{s}_1K-PNG_Displacement.png", T::Depth}},
                 dx,
                 "{s}_1K-PNG_Displacement.png",
                 R,
                 true,
                 "{s}_1K-PNG_NormalDX.png",
                 "{s}_1K-PNG_Color.png",
                 {},
                 {},
                 {}});
    c.push_back({"quixel",
                 {{"{s}_2K_Albedo.jpg", T::Albedo},
                  {"{s}_2K_Normal.png", T::Normal},
                  {"{s}_2K_Displacement.exr", T::Height},
                  {"{s}_2K_Roughness.jpg", T::Grey},
                  {"{s}_2K_AO.jpg", T::Grey},
                  {"{s}_2K_Cavity.jpg", T::Grey}},
                 std::nullopt,
                 "{s}_2K_Displacement.exr",
                 R,
                 false,
                 "{s}_2K_Normal.png",
                 "{s}_2K_Albedo.jpg",
                 {"{s}_2K_Roughness.jpg", R},
                 {"{s}_2K_AO.jpg", R},
                 {}});
    c.push_back({"unreal-orm",
                 {{"T_{s}_BaseColor.png", T::Albedo},
                  {"T_{s}_Normal_DirectX.png", T::Normal},
                  {"T_{s}_Height.png", T::Height},
                  {"T_{s}_OcclusionRoughnessMetallic.png", T::Packed}},
                 dx,
                 "T_{s}_Height.png",
                 R,
                 false,
                 "T_{s}_Normal_DirectX.png",
                 "T_{s}_BaseColor.png",
                 {"T_{s}_OcclusionRoughnessMetallic.png", G},
                 {"T_{s}_OcclusionRoughnessMetallic.png", R},
                 {"T_{s}_OcclusionRoughnessMetallic.png", B}});
    c.push_back({"unreal-d-nrm-h-ORM",
                 {{"T_{s}_D.png", T::Albedo},
                  {"T_{s}_nrm.png", T::Normal},
                  {"T_{s}_H.png", T::Height},
                  {"T_{s}_ORM.png", T::Packed}},
                 std::nullopt,
                 "T_{s}_H.png",
                 R,
                 false,
                 "T_{s}_nrm.png",
                 "T_{s}_D.png",
                 {"T_{s}_ORM.png", G},
                 {"T_{s}_ORM.png", R},
                 {"T_{s}_ORM.png", B}});
    c.push_back({"unity-hdrp-mask-map",
                 {{"{s}_BaseColor.png", T::Albedo},
                  {"{s}_Normal_OpenGL.png", T::Normal},
                  {"{s}_Height.png", T::Height},
                  {"{s}_MaskMap.png", T::Packed}},
                 gl,
                 "{s}_Height.png",
                 R,
                 false,
                 "{s}_Normal_OpenGL.png",
                 "{s}_BaseColor.png",
                 {"{s}_MaskMap.png", A, true},
                 {"{s}_MaskMap.png", G},
                 {"{s}_MaskMap.png", R}});
    c.push_back({"unity-metallic-smoothness",
                 {{"{s}_Albedo.png", T::Albedo},
                  {"{s}_Normal.png", T::Normal},
                  {"{s}_Height.png", T::Depth},
                  {"{s}_MetallicSmoothness.png", T::Packed}},
                 std::nullopt,
                 "{s}_Height.png",
                 R,
                 true,
                 "{s}_Normal.png",
                 "{s}_Albedo.png",
                 {"{s}_MetallicSmoothness.png", A, true},
                 {},
                 {"{s}_MetallicSmoothness.png", R}});
    c.push_back({"godot-orm-depth",
                 {{"{s}_albedo.png", T::Albedo},
                  {"{s}_normal.png", T::Normal},
                  {"{s}_depth.png", T::Depth},
                  {"{s}_orm.png", T::Packed}},
                 std::nullopt,
                 "{s}_depth.png",
                 R,
                 true,
                 "{s}_normal.png",
                 "{s}_albedo.png",
                 {"{s}_orm.png", G},
                 {"{s}_orm.png", R},
                 {"{s}_orm.png", B}});
    c.push_back({"cryengine-ddna",
                 {{"{s}_diff.png", T::Albedo},
                  {"{s}_ddna.png", T::NormalGlossAlpha},
                  {"{s}_displ.png", T::Height},
                  {"{s}_spec.png", T::Grey}},
                 std::nullopt,
                 "{s}_displ.png",
                 R,
                 false,
                 "{s}_ddna.png",
                 "{s}_diff.png",
                 {"{s}_ddna.png", A, true},
                 {},
                 {}});
    c.back().specular = "{s}_spec.png";
    c.push_back(
        {"tesseract-nm-height-alpha",
         {{"{s}.png", T::Albedo}, {"{s}_nm.png", T::NormalHeightAlpha}, {"{s}_s.png", T::Grey}},
         std::nullopt,
         "{s}_nm.png",
         A,
         false,
         "{s}_nm.png",
         "{s}.png",
         {},
         {},
         {}});
    c.back().specular = "{s}_s.png";
    c.push_back({"darkplaces-norm-gloss-glow",
                 {{"{s}.tga", T::Albedo},
                  {"{s}_norm.tga", T::NormalHeightAlpha},
                  {"{s}_gloss.tga", T::Grey},
                  {"{s}_glow.tga", T::Albedo}},
                 std::nullopt,
                 "{s}_norm.tga",
                 A,
                 false,
                 "{s}_norm.tga",
                 "{s}.tga",
                 {"{s}_gloss.tga", R, true},
                 {},
                 {}});
    c.push_back({"depth-in-alpha",
                 {{"{s}_col.png", T::Albedo}, {"{s}_nm.png", T::NormalDepthAlpha}},
                 std::nullopt,
                 "{s}_nm.png",
                 A,
                 true,
                 "{s}_nm.png",
                 "{s}_col.png",
                 {},
                 {},
                 {}});
    c.push_back({"doom3",
                 {{"{s}_d.png", T::Albedo},
                  {"{s}_local.png", T::Normal},
                  {"{s}_h.png", T::Height},
                  {"{s}_s.png", T::Grey}},
                 std::nullopt,
                 "{s}_h.png",
                 R,
                 false,
                 "{s}_local.png",
                 "{s}_d.png",
                 {},
                 {},
                 {}});
    c.back().specular = "{s}_s.png";
    c.push_back({"glued-tags",
                 {{"{s}1.jpg", T::Albedo}, {"{s}1z.png", T::Height}, {"{s}1n.png", T::Normal}},
                 std::nullopt,
                 "{s}1z.png",
                 R,
                 false,
                 "{s}1n.png",
                 "{s}1.jpg",
                 {},
                 {},
                 {}});
    c.push_back({"glued-z-n-s",
                 {{"{s}2.png", T::Albedo},
                  {"{s}2z.png", T::Height},
                  {"{s}2n.png", T::Normal},
                  {"{s}2s.png", T::Grey}},
                 std::nullopt,
                 "{s}2z.png",
                 R,
                 false,
                 "{s}2n.png",
                 "{s}2.png",
                 {},
                 {},
                 {}});
    c.back().specular = "{s}2s.png";
    c.push_back({"glued-d-n-h",
                 {{"{s}3d.png", T::Albedo}, {"{s}3h.png", T::Depth}, {"{s}3n.png", T::Normal}},
                 std::nullopt,
                 "{s}3h.png",
                 R,
                 true,
                 "{s}3n.png",
                 "{s}3d.png",
                 {},
                 {},
                 {}});
    c.push_back({"variant-letter",
                 {{"{s}1a.jpg", T::Albedo}, {"{s}1_n.png", T::NormalHeightAlpha}},
                 std::nullopt,
                 "{s}1_n.png",
                 A,
                 false,
                 "{s}1_n.png",
                 "{s}1a.jpg",
                 {},
                 {},
                 {}});
    c.push_back({"poliigon",
                 {{"{s}_COL_VAR1_3K.jpg", T::Albedo},
                  {"{s}_COL_VAR2_3K.jpg", T::Albedo},
                  {"{s}_NRM_3K.png", T::Normal},
                  {"{s}_DISP16_3K.png", T::Height},
                  {"{s}_GLOSS_3K.jpg", T::Grey},
                  {"{s}_REFL_3K.jpg", T::Grey},
                  {"{s}_AO_3K.jpg", T::Grey}},
                 std::nullopt,
                 "{s}_DISP16_3K.png",
                 R,
                 false,
                 "{s}_NRM_3K.png",
                 "{s}_COL_VAR1_3K.jpg",
                 {"{s}_GLOSS_3K.jpg", R, true},
                 {"{s}_AO_3K.jpg", R},
                 {}});
    c.back().specular = "{s}_REFL_3K.jpg";
    c.push_back({"z-n-plain-albedo",
                 {{"{s}.png", T::Albedo}, {"{s}_z.png", T::Height}, {"{s}_n.png", T::Normal}},
                 std::nullopt,
                 "{s}_z.png",
                 R,
                 false,
                 "{s}_n.png",
                 "{s}.png",
                 {},
                 {},
                 {}});
    c.push_back(
        {"hgt-nrm-Color",
         {{"{s}_Color.png", T::Albedo}, {"{s}_NRM.png", T::Normal}, {"{s}_hgt.png", T::Depth}},
         std::nullopt,
         "{s}_hgt.png",
         R,
         true,
         "{s}_NRM.png",
         "{s}_Color.png",
         {},
         {},
         {}});
    c.push_back({"heightmap-nor-dx-col",
                 {{"{s}_col.jpg", T::Albedo},
                  {"{s}_nor_dx.png", T::Normal},
                  {"{s}_heightmap.png", T::Height}},
                 dx,
                 "{s}_heightmap.png",
                 R,
                 false,
                 "{s}_nor_dx.png",
                 "{s}_col.jpg",
                 {},
                 {},
                 {}});
    c.push_back({"grey-bump-is-height",
                 {{"{s}_albedo.png", T::Albedo},
                  {"{s}_normal.png", T::Normal},
                  {"{s}_bump.png", T::Height}},
                 std::nullopt,
                 "{s}_bump.png",
                 R,
                 false,
                 "{s}_normal.png",
                 "{s}_albedo.png",
                 {},
                 {},
                 {}});
    c.push_back({"bump-that-is-a-normal-map",
                 {{"{s}.png", T::Albedo}, {"{s}_bump.png", T::Normal}, {"{s}_disp.png", T::Height}},
                 std::nullopt,
                 "{s}_disp.png",
                 R,
                 false,
                 "{s}_bump.png",
                 "{s}.png",
                 {},
                 {},
                 {}});
    c.push_back({"grey-named-after-the-set-is-height",
                 {{"{s}.png", T::Depth}, {"{s}_n.png", T::Normal}, {"{s}_d.png", T::Albedo}},
                 std::nullopt,
                 "{s}.png",
                 R,
                 true,
                 "{s}_n.png",
                 "{s}_d.png",
                 {},
                 {},
                 {}});
    c.push_back({"normal-named-after-the-set",
                 {{"{s}.png", T::Normal}, {"{s}_disp.png", T::Height}, {"{s}_diff.png", T::Albedo}},
                 std::nullopt,
                 "{s}_disp.png",
                 R,
                 false,
                 "{s}.png",
                 "{s}_diff.png",
                 {},
                 {},
                 {}});
    return c;
}

bool endsWith(const std::string& path, const std::string& name) {
    return name.empty() ? path.empty() : path.ends_with("/" + name);
}

} // namespace

class TextureSetConventionsTest : public QObject {
    Q_OBJECT
private slots:
    void everyConventionImportsRight_data() {
        QTest::addColumn<int>("index");
        QTest::addColumn<unsigned>("seed");
        const std::vector<Convention> all = conventions();
        for (std::size_t i = 0; i < all.size(); ++i)
            for (unsigned seed : {1u + static_cast<unsigned>(i) % 3, 5u + static_cast<unsigned>(i)})
                QTest::addRow("%s-seed%u", all[i].name.c_str(), seed) << int(i) << seed;
    }
    void everyConventionImportsRight() {
        QFETCH(int, index);
        QFETCH(unsigned, seed);
        const Convention c = conventions()[static_cast<std::size_t>(index)];
        const std::string stem = seed % 2 ? "Rock" : "wall";
        const NormalGreen green =
            c.green.value_or(seed % 4 < 2 ? NormalGreen::OpenGL : NormalGreen::DirectX);
        QTemporaryDir dir;
        std::vector<ConventionFile> files = c.files;
        for (ConventionFile& f : files)
            f.name = named(f.name, stem);
        const ConventionTruth truth =
            writeConventionSet(dir.path().toStdString(), files, seed, green);
        QVERIFY(writeTextFile(dir.filePath("notes.txt").toStdString(), "from a library"));

        const Result<TextureSetPlan> plan =
            planTextureSet(*folderFiles(dir.path().toStdString()), "dir");
        QVERIFY2(plan, plan ? "" : plan.error().message.c_str());
        const Result<ImportedSet> set = importTextureSet(*plan);
        QVERIFY2(set, set ? "" : set.error().message.c_str());
        std::string report;
        for (const std::string& line : importSummary(*set))
            report += line + "\n";
        const Material& m = set->material;
        const char* why = report.c_str();
        QVERIFY2(endsWith(m.maps.height, named(c.height, stem)), why);
        QVERIFY2(m.heightChannel == c.heightChannel, why);
        QVERIFY2(m.heightIsDepth == c.depth, why);
        QVERIFY2(endsWith(m.maps.normal, named(c.normal, stem)), why);
        QVERIFY2(m.normalGreen == green, why);
        QVERIFY2(endsWith(m.maps.albedo, named(c.albedo, stem)), why);
        QVERIFY2(endsWith(m.maps.roughness, named(c.roughness.file, stem)), why);
        QVERIFY2(endsWith(m.maps.ao, named(c.ao.file, stem)), why);
        QVERIFY2(endsWith(m.maps.metallic, named(c.metallic.file, stem)), why);
        QVERIFY2(endsWith(m.maps.specular, named(c.specular, stem)), why);
        QVERIFY2(set->assets.specular.empty() == c.specular.empty(), why);
        if (!c.roughness.file.empty()) {
            QVERIFY2(m.surface.roughness == c.roughness.channel &&
                         m.surface.gloss == c.roughness.gloss,
                     why);
            QVERIFY(!set->assets.roughness.empty());
        }
        if (!c.ao.file.empty())
            QVERIFY2(m.surface.ao == c.ao.channel, why);
        if (!c.metallic.file.empty())
            QVERIFY2(m.surface.metallic == c.metallic.channel, why);
        // A packed file's channel arrives as the map, gloss inverted.
        auto packed = [&](const Channel& ch, const Image& map) {
            const bool isPacked = std::any_of(c.files.begin(), c.files.end(), [&](const auto& f) {
                return f.name == ch.file && f.texels == Texels::Packed;
            });
            if (!isPacked)
                return true;
            if (map.empty())
                return false;
            const int k = static_cast<int>(ch.channel);
            const float want = ch.gloss ? 1.0f - packedValue(k, 3, 5) : packedValue(k, 3, 5);
            return std::abs(map.at(3, 5) - want) <= 0.5f / 255.0f + 1e-6f;
        };
        QVERIFY2(packed(c.roughness, set->assets.roughness), why);
        QVERIFY2(packed(c.ao, set->assets.ao), why);
        QVERIFY2(packed(c.metallic, set->assets.metallic), why);
        // The height, white = high, as written (to the file's precision).
        const bool exact16 = c.heightChannel == HeightChannel::Red && !c.height.ends_with(".tga") &&
                             !c.height.ends_with(".jpg");
        const float tolerance = exact16 ? 1.0f / 65535.0f + 1e-6f : 0.5f / 255.0f + 1e-6f;
        float worst = 0.0f;
        for (std::size_t i = 0; i < truth.height.texels.size(); ++i)
            worst =
                std::max(worst, std::abs(set->assets.height.texels[i] - truth.height.texels[i]));
        QVERIFY2(worst <= tolerance, qPrintable(QString("height off by %1\n").arg(worst) + why));
        // Every file is in the report.
        for (const ConventionFile& f : files)
            QVERIFY2(report.find(f.name) != std::string::npos, (f.name + "\n" + report).c_str());
        QVERIFY(report.find("Ignored: notes.txt (not an image file)") != std::string::npos);
    }
};

QTEST_GUILESS_MAIN(TextureSetConventionsTest)
#include "TextureSetConventionsTest.moc"

// File names as texture libraries, tools and games write them, read into a set's name, a map tag
// and a green convention; the vocabulary table itself is well-formed.

#include "parallax/material/MapFileName.h"

#include "parallax/material/MapKind.h"

#include <QtTest>
#include <set>

using namespace px;

Q_DECLARE_METATYPE(px::MapRole)

class MapFileNameTest : public QObject {
    Q_OBJECT
private slots:
    void namesAsPeopleWriteThem_data() {
        QTest::addColumn<QString>("file");
        QTest::addColumn<QString>("stem");
        QTest::addColumn<int>("role"); // -1: no tag
        QTest::addColumn<int>("green");
        QTest::addColumn<bool>("glued");
        auto row = [](const char* file, const char* stem, int role,
                      GreenHint green = GreenHint::None, bool glued = false) {
            QTest::newRow(file) << QString(file) << QString(stem) << role << static_cast<int>(green)
                                << glued;
        };
        const int albedo = static_cast<int>(MapRole::Albedo),
                  height = static_cast<int>(MapRole::Height),
                  normal = static_cast<int>(MapRole::Normal),
                  bump = static_cast<int>(MapRole::Bump),
                  rough = static_cast<int>(MapRole::Roughness),
                  gloss = static_cast<int>(MapRole::Gloss), orm = static_cast<int>(MapRole::Orm),
                  spec = static_cast<int>(MapRole::Specular),
                  unused = static_cast<int>(MapRole::Unused), ao = static_cast<int>(MapRole::Ao);
        // Poly Haven.
        row("brick_wall_001_diff_1k.jpg", "brick_wall_001", albedo);
        row("brick_wall_001_nor_gl_1k.exr", "brick_wall_001", normal, GreenHint::OpenGL);
        row("brick_wall_001_nor_dx_2k.png", "brick_wall_001", normal, GreenHint::DirectX);
        row("brick_wall_001_disp_4k.png", "brick_wall_001", height);
        row("brick_wall_001_arm_1k.jpg", "brick_wall_001", orm);
        row("brick_wall_001_rough_1k.jpg", "brick_wall_001", rough);
        row("brick_wall_001_bump_1k.png", "brick_wall_001", bump);
        // ambientCG, older and newer.
        row("Bricks076C_1K-PNG_Color.png", "Bricks076C", albedo);
        row("Bricks076C_1K_NormalGL.jpg", "Bricks076C", normal, GreenHint::OpenGL);
        row("Bricks076C_2K-JPG_NormalDX.jpg", "Bricks076C", normal, GreenHint::DirectX);
        row("Bricks076C_1K-PNG_Displacement.png", "Bricks076C", height);
        row("Bricks076C_1K-PNG_AmbientOcclusion.png", "Bricks076C", ao);
        row("Bricks076C_1K-PNG.png", "Bricks076C", -1); // the preview: no tag
        // Quixel, Substance, Unreal, Unity.
        row("rock_sloo2_2K_Albedo.jpg", "rock_sloo2", albedo);
        row("rock_sloo2_4K_Normal_LOD0.jpg", "rock_sloo2", normal);
        row("rock_sloo2_2K_Cavity.jpg", "rock_sloo2", unused);
        row("Wall_BaseColor.png", "Wall", albedo);
        row("Wall_Normal_OpenGL.png", "Wall", normal, GreenHint::OpenGL);
        row("Wall_Normal_DirectX.png", "Wall", normal, GreenHint::DirectX);
        row("Wall_OcclusionRoughnessMetallic.png", "Wall", orm);
        row("Wall_Mixed_AO.png", "Wall", ao);
        row("Wall_MaskMap.png", "Wall", static_cast<int>(MapRole::MaskMap));
        row("Wall_MetallicSmoothness.png", "Wall", static_cast<int>(MapRole::MetallicSmoothness));
        row("T_Wall_ORM.png", "T_Wall", orm);
        row("T_Wall_D.png", "T_Wall", albedo);
        row("Wall_BentNormal.png", "Wall", unused);
        // Unity's property names, and "map" after a tag.
        row("Rock_MainTex.png", "Rock", albedo);
        row("Rock_BumpMap.png", "Rock", bump);
        row("Rock_ParallaxMap.png", "Rock", height);
        row("Rock_OcclusionMap.png", "Rock", ao);
        row("Rock_MetallicGlossMap.png", "Rock", static_cast<int>(MapRole::MetallicSmoothness));
        row("rock_diffuse_map.jpg", "rock", albedo);
        row("rock_mask_map.png", "rock", static_cast<int>(MapRole::MaskMap));
        row("treasure_map.png", "treasure_map", -1);
        // Poliigon.
        row("Planks_COL_VAR1_3K.jpg", "Planks", albedo);
        row("Planks_DISP16_3K.png", "Planks", height);
        row("Planks_NRM16_3K.png", "Planks", normal);
        row("Planks_GLOSS_3K.jpg", "Planks", gloss);
        row("Planks_REFL_3K.jpg", "Planks", spec);
        // Engines and games.
        row("metal_ddna.dds.png", "metal", static_cast<int>(MapRole::NormalGloss));
        row("metal_ddna.png", "metal", static_cast<int>(MapRole::NormalGloss));
        row("metal_displ.png", "metal", height);
        row("tech1_nm.png", "tech1", normal);
        row("tech1_s.png", "tech1", spec);
        row("floor_norm.tga", "floor", normal);
        row("floor_glow.tga", "floor", unused);
        row("wall_local.tga", "wall", normal);
        row("wall_h.tga", "wall", height);
        row("crate1_n.png", "crate1", normal);
        row("crate1a.jpg", "crate1a", -1);
        row("stone01z.png", "stone01", height, GreenHint::None, true);
        row("stone01n.png", "stone01", normal, GreenHint::None, true);
        row("stonez.png", "stone", height, GreenHint::None, true);
        row("wall_hgt.png", "wall", height);
        row("wall heightmap.png", "wall", height);
        row("WallHeight.png", "Wall", height);
        row("wall_nor_gl.png", "wall", normal, GreenHint::OpenGL);
        // Only a tag: the set is the folder's.
        row("Displacement.png", "", height);
        row("normal.png", "", normal);
        // Not tags.
        row("grasp.png", "grasp", -1);
        row("photo_2048.jpg", "photo", -1);
        row("rock_gl.png", "rock_gl", -1); // a green word with no normal tag before it
    }
    void namesAsPeopleWriteThem() {
        QFETCH(QString, file);
        QFETCH(QString, stem);
        QFETCH(int, role);
        QFETCH(int, green);
        QFETCH(bool, glued);
        const std::vector<NameReading> readings =
            readMapFileName("/some/folder/" + file.toStdString());
        QVERIFY(!readings.empty());
        QVERIFY(!readings.back().tag); // the plain reading is always last
        const NameReading& r = readings.front();
        QCOMPARE(QString::fromStdString(r.stem), stem);
        QCOMPARE(r.tag ? static_cast<int>(r.tag->role) : -1, role);
        QCOMPARE(static_cast<int>(r.green), green);
        if (r.tag)
            QCOMPARE(r.glued, glued);
    }

    void wordsSplitOnSeparatorsCaseAndDigits() {
        const std::vector<NameWord> w = splitName("Bricks076C_1K-PNG_NormalGL");
        QStringList words;
        for (const NameWord& word : w)
            words << QString::fromStdString(word.text) + (word.glued ? "+" : "");
        QCOMPARE(words.join(' '), QString("bricks 076+ c+ 1k png normal gl"));
        QStringList more;
        for (const NameWord& word : splitName("HDRPMask_4096x4096_16bit_LOD2"))
            more << QString::fromStdString(word.text);
        QCOMPARE(more.join(' '), QString("hdrp mask 4096x4096 16bit lod2"));
    }

    void theVocabularyIsOneTableWithoutClashes() {
        std::set<std::string_view> seen;
        for (const MapTag& tag : mapTags()) {
            QVERIFY2(seen.insert(tag.words).second, tag.words.data());
            QVERIFY(!tag.origin.empty());
            for (char c : tag.words)
                QVERIFY2(c == ' ' || (c >= 'a' && c <= 'z'), tag.words.data());
            QVERIFY2(!isNeutralWord(tag.words), tag.words.data());
            QVERIFY(findMapTag(tag.words) == &tag);
            QVERIFY(tag.role != MapRole::Unused || !tag.what.empty());
        }
        // The node wrangler's default tags are all there.
        for (const char* word : {"diffuse",      "diff",         "albedo",
                                 "col",          "color",        "basecolor",
                                 "metallic",     "metalness",    "metal",
                                 "mtl",          "specularity",  "specular",
                                 "spec",         "spc",          "normal",
                                 "nor",          "nrm",          "nrml",
                                 "norm",         "bump",         "bmp",
                                 "roughness",    "rough",        "rgh",
                                 "gloss",        "glossy",       "glossiness",
                                 "displacement", "displace",     "disp",
                                 "dsp",          "height",       "heightmap",
                                 "transmission", "transparency", "emission",
                                 "emissive",     "emit",         "alpha",
                                 "opacity",      "ao",           "ambient occlusion"})
            QVERIFY2(findMapTag(word), word);
    }

    void oneFileOnItsOwnIsKnownByAFirmTagOnly() {
        const auto normal = mapKindFromFileName("Rock_2K_NormalDX.png");
        QVERIFY(normal && normal->kind == MapKind::Normal);
        QCOMPARE(QString::fromStdString(normal->setName), QString("Rock"));
        const auto depth = mapKindFromFileName("rock_depth.exr");
        QVERIFY(depth && depth->kind == MapKind::Height && depth->depth);
        QVERIFY(!mapKindFromFileName("stone01z.png")); // glued: needs its siblings
        QVERIFY(!mapKindFromFileName("rock_arm.png")); // packed: a set's import reads it
        QVERIFY(!mapKindFromFileName("bumpiness.png"));
    }
};

QTEST_GUILESS_MAIN(MapFileNameTest)
#include "MapFileNameTest.moc"

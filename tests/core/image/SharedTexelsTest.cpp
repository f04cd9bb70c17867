// Maps share their texels between copies until one writes: a copy of an 8192² map costs a
// pointer, a write never shows in another copy, and a grey image read from a file becomes a
// height field without a second buffer.

#include "parallax/bake/ConeMap.h"
#include "parallax/heightfield/HeightField.h"
#include "parallax/heightfield/HeightFieldLoader.h"
#include "parallax/image/Image.h"
#include "parallax/material/MaterialAssets.h"

#include <QtTest>
#include <algorithm>
#include <utility>
#include <vector>

using namespace px;

class SharedTexelsTest : public QObject {
    Q_OBJECT

private slots:
    void copiesShareUntilOneWrites() {
        HeightField a(64, 32, 0.25f);
        const HeightField b = a;
        QVERIFY(a.texels.sharesWith(b.texels));
        QCOMPARE(std::as_const(a).texels.data(), b.texels.data()); // non-const data() writes
        // Reading through a const view keeps them shared.
        const HeightField& view = a;
        QCOMPARE(view.at(3, 4), 0.25f);
        QVERIFY(a.texels.sharesWith(b.texels));
        // Writing gives the writer its own texels; the other copy is unchanged.
        a.at(3, 4) = 1.0f;
        QVERIFY(!a.texels.sharesWith(b.texels));
        QCOMPARE(b.at(3, 4), 0.25f);
        QCOMPARE(a.at(3, 4), 1.0f);
        QCOMPARE(std::count(a.texels.begin(), a.texels.end(), 0.25f), 64 * 32 - 1);
        // The sole owner writes in place.
        const float* before = a.texels.data();
        std::fill(a.texels.begin(), a.texels.end(), 0.5f);
        QCOMPARE(static_cast<const HeightField&>(a).texels.data(), before);
    }

    void equalityComparesTexels() {
        Image a(4, 4, 3), b(4, 4, 3);
        QVERIFY(a.pixels == b.pixels); // equal, not shared
        QVERIFY(!a.pixels.sharesWith(b.pixels));
        b.at(1, 2, 2) = 0.5f;
        QVERIFY(!(a.pixels == b.pixels));
        const Image c = b;
        QVERIFY(c.pixels == b.pixels);
        QVERIFY(SharedTexels<float>() == SharedTexels<float>());
        QCOMPARE(SharedTexels<float>().size(), std::size_t(0));
        QVERIFY(SharedTexels<float>().begin() == SharedTexels<float>().end());
    }

    // A moved-from map is empty, as a moved-from vector is; its old texels live on in the target.
    void movesTakeTheTexels() {
        ConeMap cones(ConeKind::Relaxed, 8, 8);
        cones.g(2, 2) = 0.125f;
        const float* texels = static_cast<const ConeMap&>(cones).sqrtRatio.data();
        ConeMap moved = std::move(cones);
        QCOMPARE(static_cast<const ConeMap&>(moved).sqrtRatio.data(), texels);
        QCOMPARE(moved.g(2, 2), 0.125f);
    }

    // A document's snapshot, a bake's copy and the renderer's copy of the maps are one buffer.
    void materialAssetsCopiesShareEveryMap() {
        MaterialAssets assets;
        assets.height = HeightField(128, 128, 0.5f);
        assets.albedo = Image(128, 128, 3);
        assets.relaxedCone = ConeMap(ConeKind::Relaxed, 128, 128);
        const MaterialAssets copy = assets;
        QVERIFY(copy.height.texels.sharesWith(assets.height.texels));
        QVERIFY(copy.albedo.pixels.sharesWith(assets.albedo.pixels));
        QVERIFY(copy.relaxedCone.sqrtRatio.sharesWith(assets.relaxedCone.sqrtRatio));
    }

    // A one-channel image moved into heightFieldFromImage lends its texels: no second buffer.
    // With invert, the field writes in place (it is the only owner); a kept image is not written.
    void greyImageBecomesTheFieldWithoutACopy() {
        Image grey(16, 8, 1);
        for (std::size_t i = 0; i < grey.pixels.size(); ++i)
            grey.pixels[i] = static_cast<float>(i % 7) / 7.0f;
        const Image kept = grey;
        const float* texels = static_cast<const Image&>(grey).pixels.data();
        Result<HeightField> field = heightFieldFromImage(std::move(grey), {}, "grey.png");
        QVERIFY(field.ok());
        QCOMPARE(static_cast<const HeightField&>(*field).texels.data(), texels);
        QCOMPARE(field->at(3, 1), kept.at(3, 1));

        HeightLoadOptions invert;
        invert.invert = true;
        Result<HeightField> depth = heightFieldFromImage(kept, invert, "grey.png");
        QVERIFY(depth.ok());
        QCOMPARE(depth->at(3, 1), 1.0f - kept.at(3, 1));
        QCOMPARE(kept.at(3, 1), static_cast<float>((1 * 16 + 3) % 7) / 7.0f);
        QVERIFY(!depth->texels.sharesWith(kept.pixels));
    }
};

QTEST_APPLESS_MAIN(SharedTexelsTest)
#include "SharedTexelsTest.moc"

// Maps share their texels between copies until one writes: a copy of an 8192² map costs a
// pointer, a write never shows in another copy (also after the writer stopped checking, and across
// threads), and a grey image read from a file becomes a height field without a second buffer.

#include "parallax/bake/ConeMap.h"
#include "parallax/heightfield/HeightField.h"
#include "parallax/heightfield/HeightFieldLoader.h"
#include "parallax/image/Image.h"
#include "parallax/material/MaterialAssets.h"

#include <QtTest>
#include <algorithm>
#include <thread>
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

    // A writer that owns its texels writes in place without looking at the share count; a copy
    // made afterwards, in any way, takes that back: the next write on either side detaches, and
    // the other keeps its texels.
    void copiesAfterInPlaceWritesStillDetach() {
        auto owner = [] {
            Image image(8, 8, 1);
            image.at(1, 1) = 1.0f; // owns its texels now, writes in place from here on
            return image;
        };
        {
            Image a = owner();
            const Image b = a; // copy construction
            a.at(1, 1) = 2.0f;
            QCOMPARE(b.at(1, 1), 1.0f);
            QVERIFY(!a.pixels.sharesWith(b.pixels));
        }
        {
            Image a = owner();
            const Image& view = a;
            Image b(view); // from a const reference
            b.pixels[9] = 3.0f;
            QCOMPARE(a.at(1, 1), 1.0f);
            a.pixels.data()[9] = 4.0f;
            QCOMPARE(b.at(1, 1), 3.0f);
        }
        {
            Image a = owner(), b = owner();
            b.at(2, 2) = 5.0f; // b owns its own texels
            b = a;             // copy assignment: b forgets them
            b.at(3, 3) = 6.0f;
            QCOMPARE(a.at(3, 3), 0.0f);
            *a.pixels.begin() = 7.0f;
            QCOMPARE(b.at(0, 0), 0.0f);
        }
        {
            Image a = owner();
            const float* texels = std::as_const(a).pixels.data();
            Image moved = std::move(a); // a move keeps the owner an owner: writes stay in place
            moved.at(4, 4) = 8.0f;
            QCOMPARE(std::as_const(moved).pixels.data(), texels);
            Image other = owner();
            other = std::move(moved);
            other.at(5, 5) = 9.0f;
            QCOMPARE(std::as_const(other).pixels.data(), texels);
        }
    }

    // Copies read on other threads and let go there; then the owner writes in place (one buffer,
    // no copy), and every copy read exactly the texels it was given. A copy still held elsewhere
    // makes the owner detach.
    void copiesOnOtherThreads() {
        for (int round = 0; round < 20; ++round) {
            HeightField field(128, 128, static_cast<float>(round));
            field.at(0, 0) = -1.0f; // the owner's own texels
            const float* texels = std::as_const(field).texels.data();
            std::vector<double> sums(4, 0.0);
            std::vector<std::thread> readers;
            for (std::size_t k = 0; k < sums.size(); ++k) {
                readers.emplace_back([copy = field, &sum = sums[k]] {
                    for (float h : copy.texels)
                        sum += h;
                });
            }
            for (std::thread& t : readers)
                t.join();
            for (double sum : sums)
                QCOMPARE(sum, round * (128.0 * 128.0 - 1.0) - 1.0);
            field.at(7, 7) = 2.0f;
            QCOMPARE(std::as_const(field).texels.data(), texels); // the last owner: in place

            HeightField held = field;
            float seen = 0.0f;
            std::thread holder([&held, &seen] { seen = std::as_const(held).at(7, 7); });
            holder.join();
            QCOMPARE(seen, 2.0f);
            field.at(7, 7) = 3.0f; // `held` still shares them: detach
            QVERIFY(std::as_const(field).texels.data() != texels);
            QCOMPARE(held.at(7, 7), 2.0f);
        }
    }

    // A writer makes the texels its map's own once: a copy taken before keeps its texels, and
    // threads writing through one writer all land in the one buffer (through g() they would each
    // try to detach a shared map at once). Image, height field and cone map alike.
    void writersDetachOnceForEveryThread() {
        for (int round = 0; round < 10; ++round) {
            ConeMap cones(ConeKind::Relaxed, 96, 64);
            const ConeMap before = cones; // shared until the writer is taken
            const PlaneWriter put = cones.writer();
            QVERIFY(!cones.sqrtRatio.sharesWith(before.sqrtRatio));
            std::vector<std::thread> threads;
            threads.reserve(4);
            for (int k = 0; k < 4; ++k) {
                threads.emplace_back([&put, k] {
                    for (int y = k; y < 64; y += 4)
                        for (int x = 0; x < 96; ++x)
                            put.at(x, y) = static_cast<float>(x + 100 * y) / 8192.0f;
                });
            }
            for (std::thread& t : threads)
                t.join();
            for (int y = 0; y < 64; ++y)
                for (int x = 0; x < 96; ++x) {
                    QCOMPARE(std::as_const(cones).g(x, y),
                             static_cast<float>(x + 100 * y) / 8192.0f);
                    QCOMPARE(before.g(x, y), 1.0f);
                }
        }
        HeightField field(5, 3, 0.5f);
        const HeightField kept = field;
        field.writer().at(4, 2) = 1.0f;
        QCOMPARE(std::as_const(field).at(4, 2), 1.0f);
        QCOMPARE(kept.at(4, 2), 0.5f);
        Image image(3, 2, 4);
        const Image original = image;
        const ImageWriter put = image.writer();
        put.at(2, 1, 3) = 0.25f;
        QCOMPARE(std::as_const(image).at(2, 1, 3), 0.25f);
        QCOMPARE(std::as_const(image).pixels[image.index(2, 1, 3)], 0.25f);
        QCOMPARE(original.at(2, 1, 3), 0.0f);
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

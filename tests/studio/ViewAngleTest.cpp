// The orbit camera stays above the material's surface whatever the drag, and the camera's polar
// angle can be typed, so a given grazing angle can be reached and compared.

#include "StudioTestSupport.h"
#include "panels/ViewPanel.h"
#include "preview/ViewInteraction.h"
#include "widgets/SliderField.h"

#include <QDoubleSpinBox>

using namespace px;
using namespace px::studio;
using namespace px::studio::test;

class ViewAngleTest : public QObject {
    Q_OBJECT
    QTemporaryDir m_settings;

private slots:
    void initTestCase() { isolateSettings(m_settings); }

    void orbitNeverGoesBelowTheSurface() {
        for (double drag : {-5000.0, -400.0, -37.5, 0.0, 12.0, 400.0, 5000.0}) {
            const OrbitCamera c = orbit(defaultCamera(), QPointF(13.0, drag));
            QVERIFY(c.elevationDeg >= kMinElevation && c.elevationDeg <= kMaxElevation);
            QVERIFY2(c.position().y > 0.0f, qPrintable(QString::number(drag)));
        }
        // Repeated small drags cannot creep past the limit either.
        OrbitCamera c = defaultCamera();
        for (int i = 0; i < 1000; ++i)
            c = orbit(c, QPointF(0.0, -3.0));
        QCOMPARE(c.elevationDeg, kMinElevation);
    }

    void polarAngleIsTypedAndClamped() {
        QCOMPARE(withPolarAngle(defaultCamera(), 75.0).elevationDeg, 15.0f);
        QCOMPARE(withPolarAngle(defaultCamera(), 120.0).elevationDeg, kMinElevation);
        QCOMPARE(withPolarAngle(defaultCamera(), -10.0).elevationDeg, kMaxElevation);

        auto w = makeWindow();
        QVERIFY(w);
        QDoubleSpinBox* field = w->viewPanel()->viewAngle()->field();
        QCOMPARE(field->value(), 90.0 - w->viewports()->activeView().camera.elevationDeg);
        field->setFocus();
        field->selectAll();
        QTest::keyClicks(field, "80");
        QTest::keyClick(field, Qt::Key_Return);
        QCOMPARE(w->viewports()->activeView().camera.elevationDeg, 10.0f);
        // A drag updates the field.
        SharedView view = w->viewports()->activeView();
        view.camera = orbit(view.camera, QPointF(0.0, 20.0));
        w->viewports()->editView(view);
        QCOMPARE(field->value(), 75.0);
    }
};

QTEST_MAIN(ViewAngleTest)
#include "ViewAngleTest.moc"

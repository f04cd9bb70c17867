// File dialogs start in the folder last chosen for their kind of file, across sessions, and the
// editor's own dialogs do (widgets/FileDialogs.h). Real QFileDialogs, answered by a timer.

#include "widgets/FileDialogs.h"

#include "StudioTestSupport.h"

#include <QAction>
#include <QApplication>
#include <QFile>
#include <QFileDialog>
#include <QLineEdit>
#include <QPointer>
#include <QTimer>
#include <memory>

using namespace px;
using namespace px::studio;
using namespace px::studio::test;

namespace {

// The folder the next file dialog opened in; it then chooses `answer` (empty: Cancel).
struct DialogAnswer {
    QString openedIn;
    QString selected; // the file name in the dialog's name field when it opened
    bool seen = false;
};

// A file is chosen again on every tick until the dialog holds it (while its model still lists
// the folder it may replace the name just typed, and accept() would then only change folder); the
// timer stops once that dialog, and only that one, has gone.
void answerNextDialog(const QString& answer, DialogAnswer* seen) {
    auto* timer = new QTimer;
    timer->setInterval(10);
    auto target = std::make_shared<QPointer<QFileDialog>>();
    QObject::connect(timer, &QTimer::timeout, [timer, answer, seen, target] {
        auto* dialog = qobject_cast<QFileDialog*>(QApplication::activeModalWidget());
        if (seen->seen && (target->isNull() || dialog != target->data())) {
            timer->stop();
            timer->deleteLater();
            return;
        }
        if (!dialog || (seen->seen && dialog->fileMode() == QFileDialog::Directory))
            return;
        if (!seen->seen) {
            *target = dialog;
            // Done when that dialog is (a later dialog may reuse its address).
            QObject::connect(dialog, &QDialog::finished, timer, [timer] {
                timer->stop();
                timer->deleteLater();
            });
            seen->openedIn = QDir(dialog->directory()).absolutePath();
            const QStringList selected = dialog->selectedFiles();
            seen->selected =
                selected.isEmpty() ? QString() : QFileInfo(selected.first()).fileName();
            seen->seen = true;
        }
        if (answer.isEmpty()) {
            dialog->reject();
            return;
        }
        if (dialog->fileMode() == QFileDialog::Directory) {
            // Go into the folder and choose it with no name typed, as a user does: selectFile()
            // with a folder races the dialog's model, which may still be listing its parent.
            dialog->setDirectory(answer);
            if (auto* name = dialog->findChild<QLineEdit*>("fileNameEdit"))
                name->clear();
        } else {
            dialog->selectFile(answer);
            if (QDir::cleanPath(dialog->selectedFiles().value(0)) != QDir::cleanPath(answer))
                return;
        }
        QMetaObject::invokeMethod(dialog, &QDialog::accept); // protected in QFileDialog
    });
    timer->start();
}

QString touch(const QString& path) {
    QDir().mkpath(QFileInfo(path).absolutePath());
    QFile file(path);
    file.open(QIODevice::WriteOnly);
    file.write("x");
    return QFileInfo(path).absoluteFilePath();
}

} // namespace

class FileDialogsTest : public QObject {
    Q_OBJECT
    QTemporaryDir m_settings, m_dir;

    QString folder(const QString& name) const {
        QDir().mkpath(m_dir.filePath(name));
        return QDir(m_dir.filePath(name)).absolutePath();
    }

private slots:
    void initTestCase() { isolateSettings(m_settings); }
    void init() { QSettings().remove(QStringLiteral("fileDialogs")); }

    // A map dialog, then a mesh dialog elsewhere: each opens where its own kind was chosen last.
    void eachKindStartsWhereItWasLastChosen() {
        const QString maps = folder("textures"), meshes = folder("meshes");
        const QString fallback = folder("material");
        DialogAnswer a;
        answerNextDialog(touch(maps + "/bricks_height.png"), &a);
        QCOMPARE(askOpenFile(nullptr, FileKind::Map, "Load", "All files (*)", fallback),
                 maps + "/bricks_height.png");
        QVERIFY(a.seen);
        QCOMPARE(a.openedIn, fallback); // nothing remembered yet: the fallback
        DialogAnswer b;
        answerNextDialog(touch(meshes + "/torus.obj"), &b);
        QCOMPARE(askOpenFile(nullptr, FileKind::Mesh, "Load", "All files (*)", fallback),
                 meshes + "/torus.obj");
        QCOMPARE(b.openedIn, fallback); // the map's folder is the maps' alone
        DialogAnswer c, d;
        answerNextDialog({}, &c);
        QVERIFY(askOpenFile(nullptr, FileKind::Map, "Load", "All files (*)", fallback).isEmpty());
        QCOMPARE(c.openedIn, maps);
        answerNextDialog({}, &d);
        QVERIFY(askOpenFile(nullptr, FileKind::Mesh, "Load", "All files (*)", fallback).isEmpty());
        QCOMPARE(d.openedIn, meshes);
        // A cancelled dialog forgets nothing.
        QCOMPARE(lastFolder(FileKind::Map), maps);
    }

    // A save dialog offers its suggested name in the folder last saved to; a whole path is kept.
    void saveDialogsSuggestInTheRememberedFolder() {
        const QString pictures = folder("pictures");
        DialogAnswer a;
        answerNextDialog(pictures + "/shot.png", &a);
        QCOMPARE(askSaveFile(nullptr, FileKind::Picture, "Save", "view.png", "PNG (*.png)"),
                 pictures + "/shot.png");
        DialogAnswer b;
        answerNextDialog({}, &b);
        askSaveFile(nullptr, FileKind::Picture, "Save", "view.png", "PNG (*.png)");
        QCOMPARE(b.openedIn, pictures);
        QCOMPARE(b.selected, QString("view.png"));
        const QString elsewhere = folder("elsewhere");
        DialogAnswer c;
        answerNextDialog({}, &c);
        askSaveFile(nullptr, FileKind::Picture, "Save", elsewhere + "/bricks.png", "PNG (*.png)");
        QCOMPARE(c.openedIn, elsewhere);
    }

    // A texture set's folder: the next dialog opens beside it (the next set is a sibling).
    void aTextureFolderRemembersWhereItLies() {
        const QString library = folder("library");
        const QString set = folder("library/bricks2");
        DialogAnswer a;
        answerNextDialog(set, &a);
        QCOMPARE(askFolder(nullptr, FileKind::TextureFolder, "Import"), set);
        QCOMPARE(lastFolder(FileKind::TextureFolder), library);
        rememberChoice(FileKind::ExportFolder, set);
        QCOMPARE(lastFolder(FileKind::ExportFolder), set);
    }

    // A remembered folder that was removed is forgotten: the fallback again.
    void aFolderThatIsGoneIsForgotten() {
        const QString gone = folder("gone");
        rememberChoice(FileKind::Environment, gone + "/sky.hdr");
        QCOMPARE(lastFolder(FileKind::Environment), gone);
        QVERIFY(QDir(gone).removeRecursively());
        QVERIFY(lastFolder(FileKind::Environment).isEmpty());
        const QString fallback = folder("here");
        DialogAnswer a;
        answerNextDialog({}, &a);
        askOpenFile(nullptr, FileKind::Environment, "Load", "All files (*)", fallback);
        QCOMPARE(a.openedIn, fallback);
    }

    // The editor's Load Mesh (Ctrl+M) opens where the last mesh was chosen, in another session.
    void theEditorsDialogsStartWhereTheUserWas() {
        const QString meshes = folder("session-meshes");
        rememberChoice(FileKind::Mesh, meshes + "/statue.glb"); // an earlier session
        auto w = makeWindow(1, 16);
        QVERIFY(w);
        QAction* load = nullptr;
        for (QAction* action : w->findChildren<QAction*>())
            if (action->shortcut() == QKeySequence(Qt::CTRL | Qt::Key_M))
                load = action;
        QVERIFY(load);
        DialogAnswer a;
        answerNextDialog({}, &a);
        load->trigger();
        QVERIFY(a.seen);
        QCOMPARE(a.openedIn, meshes);
    }
};

QTEST_MAIN(FileDialogsTest)
#include "FileDialogsTest.moc"

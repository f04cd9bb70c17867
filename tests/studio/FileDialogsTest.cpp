// File dialogs start in the folder last chosen for their kind of file, across sessions, and the
// editor's own dialogs do (widgets/FileDialogs.h). The real QFileDialogs, set up as the user sees
// them, answered through the dialog runner instead of exec(): a timer typing into a modal dialog
// races its folder model and once hung the suite.

#include "widgets/FileDialogs.h"

#include "StudioTestSupport.h"

#include <QAction>
#include <QApplication>
#include <QFile>
#include <QFileDialog>
#include <memory>

using namespace px;
using namespace px::studio;
using namespace px::studio::test;

namespace {

// What the next file dialog showed when it opened; it then answers `answer` (empty: Cancel).
struct DialogAnswer {
    QString openedIn;
    QString selected; // the file name in the dialog's name field when it opened
    QFileDialog::FileMode mode = QFileDialog::AnyFile;
    QFileDialog::AcceptMode accept = QFileDialog::AcceptOpen;
    int shown = 0;
};

// Answers every dialog until it goes out of scope, recording the last one in `seen`.
class AnswerDialogs {
public:
    AnswerDialogs(const QString& answer, DialogAnswer* seen)
        : m_previous(setDialogRunner([answer, seen](QFileDialog& dialog) {
              seen->openedIn = QDir(dialog.directory()).absolutePath();
              const QStringList selected = dialog.selectedFiles();
              seen->selected =
                  selected.isEmpty() ? QString() : QFileInfo(selected.first()).fileName();
              seen->mode = dialog.fileMode();
              seen->accept = dialog.acceptMode();
              ++seen->shown;
              return answer;
          })) {}
    ~AnswerDialogs() { setDialogRunner(m_previous); }
    AnswerDialogs(const AnswerDialogs&) = delete;
    AnswerDialogs& operator=(const AnswerDialogs&) = delete;

private:
    DialogRunner m_previous;
};

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
        const AnswerDialogs answerA(touch(maps + "/bricks_height.png"), &a);
        QCOMPARE(askOpenFile(nullptr, FileKind::Map, "Load", "All files (*)", fallback),
                 maps + "/bricks_height.png");
        QCOMPARE(a.shown, 1);
        QCOMPARE(a.mode, QFileDialog::ExistingFile);
        QCOMPARE(a.accept, QFileDialog::AcceptOpen);
        QCOMPARE(a.openedIn, fallback); // nothing remembered yet: the fallback
        DialogAnswer b;
        const AnswerDialogs answerB(touch(meshes + "/torus.obj"), &b);
        QCOMPARE(askOpenFile(nullptr, FileKind::Mesh, "Load", "All files (*)", fallback),
                 meshes + "/torus.obj");
        QCOMPARE(b.openedIn, fallback); // the map's folder is the maps' alone
        DialogAnswer c, d;
        const AnswerDialogs answerC(QString(), &c);
        QVERIFY(askOpenFile(nullptr, FileKind::Map, "Load", "All files (*)", fallback).isEmpty());
        QCOMPARE(c.openedIn, maps);
        const AnswerDialogs answerD(QString(), &d);
        QVERIFY(askOpenFile(nullptr, FileKind::Mesh, "Load", "All files (*)", fallback).isEmpty());
        QCOMPARE(d.openedIn, meshes);
        // A cancelled dialog forgets nothing.
        QCOMPARE(lastFolder(FileKind::Map), maps);
    }

    // A save dialog offers its suggested name in the folder last saved to; a whole path is kept.
    void saveDialogsSuggestInTheRememberedFolder() {
        const QString pictures = folder("pictures");
        DialogAnswer a;
        const AnswerDialogs answerA(pictures + "/shot.png", &a);
        QCOMPARE(askSaveFile(nullptr, FileKind::Picture, "Save", "view.png", "PNG (*.png)"),
                 pictures + "/shot.png");
        DialogAnswer b;
        const AnswerDialogs answerB(QString(), &b);
        askSaveFile(nullptr, FileKind::Picture, "Save", "view.png", "PNG (*.png)");
        QCOMPARE(b.openedIn, pictures);
        QCOMPARE(b.selected, QString("view.png"));
        QCOMPARE(b.accept, QFileDialog::AcceptSave);
        const QString elsewhere = folder("elsewhere");
        DialogAnswer c;
        const AnswerDialogs answerC(QString(), &c);
        askSaveFile(nullptr, FileKind::Picture, "Save", elsewhere + "/bricks.png", "PNG (*.png)");
        QCOMPARE(c.openedIn, elsewhere);
    }

    // A texture set's folder: the next dialog opens beside it (the next set is a sibling).
    void aTextureFolderRemembersWhereItLies() {
        const QString library = folder("library");
        const QString set = folder("library/bricks2");
        DialogAnswer a;
        const AnswerDialogs answerA(set, &a);
        QCOMPARE(askFolder(nullptr, FileKind::TextureFolder, "Import"), set);
        QCOMPARE(a.mode, QFileDialog::Directory);
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
        const AnswerDialogs answerA(QString(), &a);
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
        const AnswerDialogs answerA(QString(), &a);
        load->trigger();
        QCOMPARE(a.shown, 1);
        QCOMPARE(a.openedIn, meshes);
    }
};

QTEST_MAIN(FileDialogsTest)
#include "FileDialogsTest.moc"

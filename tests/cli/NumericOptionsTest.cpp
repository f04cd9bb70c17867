// Every numeric option of every command, found by walking the CLI11 app, reads numbers one way
// (parallax/NumberText.h): NaN, infinities, text and integers that overflow are refused before
// any work with one message naming the option; nothing is wrapped or read as octal.

#include "Cli.h"

#include <QtTest>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

class NumericOptionsTest : public QObject {
    Q_OBJECT

private slots:
    void everyNumericOptionRefusesWhatIsNoNumber_data();
    void everyNumericOptionRefusesWhatIsNoNumber();
    void theIssuesCases_data();
    void theIssuesCases();
    void numbersStillRead();
};

namespace {

struct Outcome {
    int status = 0;
    std::string errors;
};

// parallax-cli ARGS in this process, its standard error captured.
Outcome runCli(const std::vector<std::string>& args) {
    std::vector<std::string> words{"parallax-cli"};
    words.insert(words.end(), args.begin(), args.end());
    std::vector<char*> argv;
    argv.reserve(words.size());
    for (std::string& w : words)
        argv.push_back(w.data());
    std::ostringstream captured;
    std::streambuf* old = std::cerr.rdbuf(captured.rdbuf());
    const int status = px::cli::run(static_cast<int>(argv.size()), argv.data());
    std::cerr.rdbuf(old);
    return {status, captured.str()};
}

struct NumericOption {
    std::string command, option, type;
    int values = 1; // how many the option takes at once
};

// Every option of every command whose type is a number, from the app itself: an option added
// later is checked without a line here.
std::vector<NumericOption> numericOptions() {
    CLI::App app;
    px::cli::addCommands(app);
    std::vector<NumericOption> out;
    for (CLI::App* command : app.get_subcommands({})) {
        for (const CLI::Option* option : command->get_options()) {
            const std::string full = option->get_type_name();
            const std::string type = full.substr(0, full.find(':'));
            if ((type != "FLOAT" && type != "INT" && type != "UINT") ||
                option->get_lnames().empty())
                continue;
            out.push_back({command->get_name(), "--" + option->get_lnames().front(), type,
                           std::max(1, option->get_type_size_min())});
        }
    }
    return out;
}

} // namespace

void NumericOptionsTest::everyNumericOptionRefusesWhatIsNoNumber_data() {
    QTest::addColumn<QString>("command");
    QTest::addColumn<QString>("option");
    QTest::addColumn<int>("values");
    QTest::addColumn<QString>("value");
    QTest::addColumn<QString>("problem");
    const std::vector<NumericOption> options = numericOptions();
    // The app has numeric options in every command that takes numbers: a walk that found few
    // would test nothing.
    QVERIFY2(options.size() >= 40, qPrintable(QString::number(options.size())));
    for (const NumericOption& o : options) {
        const QString name = QString::fromStdString(o.command + " " + o.option);
        const auto row = [&](const char* value, const char* problem) {
            QTest::newRow(qPrintable(name + " " + value))
                << QString::fromStdString(o.command) << QString::fromStdString(o.option) << o.values
                << QString(value) << QString(problem);
        };
        row("nan", "is not a finite number");
        row("-inf", "is not a finite number");
        row("1e999", "is not a finite number");
        row("0x10", "is not a number");
        row("twelve", "is not a number");
        if (o.type != "FLOAT") {
            row("4294967424", "is out of range");
            row("-99999999999999999999", "is out of range");
            row("2.5", "is not a whole number");
        }
    }
}

void NumericOptionsTest::everyNumericOptionRefusesWhatIsNoNumber() {
    QFETCH(QString, command);
    QFETCH(QString, option);
    QFETCH(int, values);
    QFETCH(QString, value);
    QFETCH(QString, problem);
    std::vector<std::string> args{command.toStdString(), option.toStdString()};
    for (int i = 0; i < values; ++i)
        args.push_back(value.toStdString());
    const Outcome run = runCli(args);
    QCOMPARE(run.status, 2);
    const std::string expected = "error: " + option.toStdString() + ": '" + value.toStdString() +
                                 "' " + problem.toStdString();
    QVERIFY2(run.errors.starts_with(expected), run.errors.c_str());
}

void NumericOptionsTest::theIssuesCases_data() {
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<int>("status");
    QTest::addColumn<QString>("message");
    const QString finite = "' is not a finite number";
    for (const char* option : {"--exposure", "--scale", "--tiling", "--softness"}) {
        QTest::newRow(qPrintable(QString("render ") + option + " nan"))
            << QStringList{"render", "--height", "h.png", option, "nan", "--out", "r.png"} << 2
            << QString("error: ") + option + ": 'nan" + finite;
    }
    QTest::newRow("sample flat --level nan --bits 32")
        << QStringList{"sample", "flat", "--level", "nan", "--bits", "32", "--out", "f.exr"} << 2
        << "error: --level: 'nan" + finite;
    QTest::newRow("bench --sweep cone:max-steps=4294967424")
        << QStringList{"bench", "--height", "h.png", "--sweep", "cone:max-steps=4294967424",
                       "--out", "b.csv"}
        << 1 << "error: cone:max-steps: '4294967424' is out of range (1 to 16777216)";
    QTest::newRow("render --light 10,nan")
        << QStringList{"render", "--height", "h.png", "--light", "10,nan", "--out", "r.png"} << 1
        << "error: --light: 'nan" + finite;
    QTest::newRow("render --size 99999999999")
        << QStringList{"render", "--height", "h.png", "--size", "99999999999", "--out", "r.png"}
        << 1 << "error: --size: '99999999999' is out of range (1 to 16384)";
    QTest::newRow("render --turntable 0")
        << QStringList{"render", "--height", "h.png", "--turntable", "0", "--out", "r.png"} << 2
        << "error: --turntable: '0' is out of range (1 to 3600)";
    QTest::newRow("render --max-triangles 0")
        << QStringList{"render", "--height", "h.png", "--max-triangles", "0", "--out", "r.png"} << 2
        << "error: --max-triangles: '0' is not positive";
}

// The cases the issue names, checked where they are refused (a --sweep or --light value is read
// by the command, after the options parse: status 1, the same words).
void NumericOptionsTest::theIssuesCases() {
    QFETCH(QStringList, args);
    QFETCH(int, status);
    QFETCH(QString, message);
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString previous = QDir::currentPath();
    QVERIFY(QDir::setCurrent(dir.path()));
    // h.png exists (so a missing file is never what is reported) and is no image: nothing is
    // read before the number is refused.
    QFile h("h.png");
    QVERIFY(h.open(QIODevice::WriteOnly));
    h.write("not read");
    h.close();
    std::vector<std::string> words;
    for (const QString& a : args)
        words.push_back(a.toStdString());
    const Outcome run = runCli(words);
    QVERIFY(QDir::setCurrent(previous));
    QCOMPARE(run.status, status);
    QVERIFY2(run.errors.starts_with(message.toStdString()), run.errors.c_str());
    // Nothing written beside the input.
    QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden), QStringList{"h.png"});
}

// Numbers that are numbers still parse: a leading '+', leading zeros (decimal), exponents.
void NumericOptionsTest::numbersStillRead() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    for (const char* size : {"+16", "016"}) {
        const std::string out = dir.filePath(QString("s%1.png").arg(size)).toStdString();
        const Outcome run =
            runCli({"sample", "flat", "--level", "5e-1", "--size", size, "--out", out});
        QVERIFY2(run.status == 0, run.errors.c_str());
        QVERIFY(QFileInfo::exists(QString::fromStdString(out)));
    }
    const Outcome real =
        runCli({"sample", "flat", "--size", "1.6e1", "--out", dir.filePath("r.png").toStdString()});
    QCOMPARE(real.status, 2);
    QVERIFY2(real.errors.starts_with("error: --size: '1.6e1' is not a whole number"),
             real.errors.c_str());
}

QTEST_GUILESS_MAIN(NumericOptionsTest)
#include "NumericOptionsTest.moc"

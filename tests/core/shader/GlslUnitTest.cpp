// The generator's GLSL front end (core/src/shader/GlslUnit.h), table by table: #if evaluation,
// the split into top-level items and the names each declares ("int a, b;" declares two), and
// reachability from main(). Each row is a small shader text with the exact expected result.

#include "shader/GlslUnit.h"

#include <QtTest>
#include <set>
#include <string>
#include <vector>

using namespace px;
using namespace px::shader;

namespace {

std::set<std::string> defineSet(const QString& names) {
    std::set<std::string> defines;
    for (const QString& n : names.split(',', Qt::SkipEmptyParts))
        defines.insert(n.toStdString());
    return defines;
}

// "a,b|f|S": the names of each item, items separated by '|'.
QString namesOf(const std::vector<GlslItem>& items) {
    QStringList out;
    for (const GlslItem& item : items) {
        QStringList names;
        for (const std::string& n : item.names)
            names << QString::fromStdString(n);
        out << names.join(',');
    }
    return out.join('|');
}

QString joined(const std::set<std::string>& names) {
    QStringList out;
    for (const std::string& n : names)
        out << QString::fromStdString(n);
    return out.join(',');
}

} // namespace

class GlslUnitTest : public QObject {
    Q_OBJECT

private slots:
    void preprocessKeepsTheTakenBranches_data();
    void preprocessKeepsTheTakenBranches();
    void preprocessErrorsNameFileAndLine_data();
    void preprocessErrorsNameFileAndLine();
    void splitNamesEveryDeclaration_data();
    void splitNamesEveryDeclaration();
    void splitKeepsCommentsAndLines();
    void splitErrorsNameFileAndLine_data();
    void splitErrorsNameFileAndLine();
    void reachability_data();
    void reachability();
};

void GlslUnitTest::preprocessKeepsTheTakenBranches_data() {
    QTest::addColumn<QString>("text");
    QTest::addColumn<QString>("defines");
    QTest::addColumn<QString>("expected"); // removed lines stay as empty lines
    QTest::newRow("if defined") << "#if A\nx\n#endif"
                                << "A"
                                << "\nx\n";
    QTest::newRow("if undefined") << "#if A\nx\n#endif"
                                  << ""
                                  << "\n\n";
    QTest::newRow("if 0 / 1") << "#if 0\na\n#endif\n#if 1\nb\n#endif"
                              << ""
                              << "\n\n\n\nb\n";
    QTest::newRow("ifdef") << "#ifdef A\nx\n#else\ny\n#endif"
                           << "A"
                           << "\nx\n\n\n";
    QTest::newRow("ifndef") << "#ifndef A\nx\n#else\ny\n#endif"
                            << "A"
                            << "\n\n\ny\n";
    QTest::newRow("defined() and !") << "#if defined(A) && !defined(B)\nx\n#endif"
                                     << "A"
                                     << "\nx\n";
    QTest::newRow("! binds tighter than &&") << "#if !A && B\nx\n#endif"
                                             << "B"
                                             << "\nx\n";
    QTest::newRow("|| below &&") << "#if A || B && C\nx\n#endif"
                                 << "A"
                                 << "\nx\n";
    QTest::newRow("parentheses") << "#if (A || B) && C\nx\n#endif"
                                 << "A"
                                 << "\n\n";
    QTest::newRow("defined without parentheses") << "#if defined A\nx\n#endif"
                                                 << "A"
                                                 << "\nx\n";
    QTest::newRow("elif: first true wins") << "#if A\na\n#elif B\nb\n#elif C\nc\n#else\nd\n#endif"
                                           << "B,C"
                                           << "\n\n\nb\n\n\n\n\n";
    QTest::newRow("else after no branch") << "#if A\na\n#elif B\nb\n#else\nd\n#endif"
                                          << ""
                                          << "\n\n\n\n\nd\n";
    QTest::newRow("true inside false stays out") << "#if A\n#if B\nx\n#endif\ny\n#endif\nz"
                                                 << "B"
                                                 << "\n\n\n\n\n\nz";
    QTest::newRow("false inside true") << "#if A\n#if B\nx\n#endif\ny\n#endif"
                                       << "A"
                                       << "\n\n\n\ny\n";
    QTest::newRow("other directives kept") << "#define K 2\n#if A\n#line 7\n#endif"
                                           << "A"
                                           << "#define K 2\n\n#line 7\n";
    QTest::newRow("indented directives") << "  #if A\n  x\n  #endif"
                                         << ""
                                         << "\n\n";
}

void GlslUnitTest::preprocessKeepsTheTakenBranches() {
    QFETCH(QString, text);
    QFETCH(QString, defines);
    QFETCH(QString, expected);
    const Result<std::string> out = preprocess(text.toStdString(), defineSet(defines), "t.glsl");
    QVERIFY2(out.ok(), out ? "" : out.error().message.c_str());
    QCOMPARE(QString::fromStdString(*out), expected);
}

void GlslUnitTest::preprocessErrorsNameFileAndLine_data() {
    QTest::addColumn<QString>("text");
    QTest::addColumn<QString>("error");
    QTest::newRow("else without if") << "x\n#else\n"
                                     << "t.glsl:2: #else without #if";
    QTest::newRow("elif without if") << "#elif A\n"
                                     << "t.glsl:1: #elif without #if";
    QTest::newRow("endif without if") << "\n\n#endif"
                                      << "t.glsl:3: #endif without #if";
    QTest::newRow("if without endif") << "#if A\nx\ny"
                                      << "t.glsl:3: #if without #endif";
    QTest::newRow("expression it cannot read") << "\n#if A + 1\n#endif"
                                               << "t.glsl:2: cannot evaluate #if A + 1";
    QTest::newRow("unclosed parenthesis") << "#if (A\n#endif"
                                          << "t.glsl:1: cannot evaluate #if (A";
    QTest::newRow("line continuation") << "#define X \\\n 1"
                                       << "t.glsl:1: line continuations";
}

void GlslUnitTest::preprocessErrorsNameFileAndLine() {
    QFETCH(QString, text);
    QFETCH(QString, error);
    const Result<std::string> out = preprocess(text.toStdString(), {}, "t.glsl");
    QVERIFY(!out.ok());
    QVERIFY2(QString::fromStdString(out.error().message).startsWith(error),
             out.error().message.c_str());
}

void GlslUnitTest::splitNamesEveryDeclaration_data() {
    QTest::addColumn<QString>("text");
    QTest::addColumn<QString>("names");
    QTest::newRow("one global") << "float a;"
                                << "a";
    QTest::newRow("two globals in one") << "int a, b;"
                                        << "a,b";
    QTest::newRow("initialisers") << "const float k = 1.0f, m = max(k, 2.0f), n;"
                                  << "k,m,n";
    QTest::newRow("arrays") << "float w[3], v[2 * 2];"
                            << "w,v";
    QTest::newRow("function") << "vec2 pxF(vec2 a, float b) {\n    return a * b;\n}"
                              << "pxF";
    QTest::newRow("prototype") << "float pxG(float x, int y);"
                               << "pxG";
    QTest::newRow("struct") << "struct PxBracket {\n    float t0, t1;\n};"
                            << "PxBracket";
    QTest::newRow("layout-qualified output") << "layout(location = 0) out vec4 pxOut;"
                                             << "pxOut";
    QTest::newRow("define") << "#define PX_K 3"
                            << "PX_K";
    QTest::newRow("other directive") << "#extension GL_X : enable"
                                     << "";
    QTest::newRow("several items") << "in vec2 vUv;\nint a, b;\nvoid main() { a = b; }"
                                   << "vUv|a,b|main";
    QTest::newRow("numbers are no names") << "const float pxBig = 1.0e30f;"
                                          << "pxBig";
}

void GlslUnitTest::splitNamesEveryDeclaration() {
    QFETCH(QString, text);
    QFETCH(QString, names);
    const Result<std::vector<GlslItem>> items = splitItems(text.toStdString(), 2, "t.glsl");
    QVERIFY2(items.ok(), items ? "" : items.error().message.c_str());
    QCOMPARE(namesOf(*items), names);
}

void GlslUnitTest::splitKeepsCommentsAndLines() {
    const std::string text = "// about a\n"
                             "float a; // trailing\n"
                             "\n"
                             "// detached by the blank line below\n"
                             "\n"
                             "/* about f */\n"
                             "float f(float x) {\n"
                             "    return a * x; // uses a\n"
                             "}\n";
    const Result<std::vector<GlslItem>> items = splitItems(text, 3, "t.glsl");
    QVERIFY(items.ok());
    QCOMPARE(items->size(), std::size_t{2});
    const GlslItem& a = (*items)[0];
    QCOMPARE(a.text, std::string("// about a\nfloat a; // trailing\n"));
    QCOMPARE(a.firstLine, 1);
    QCOMPARE(a.file, 3);
    const GlslItem& f = (*items)[1];
    QCOMPARE(f.text,
             std::string("/* about f */\nfloat f(float x) {\n    return a * x; // uses a\n}\n"));
    QCOMPARE(f.firstLine, 6);
    // References come from code only, not from comments, and not the item's own names.
    QCOMPARE(joined(f.references), QString("a,float,return,x"));
}

void GlslUnitTest::splitErrorsNameFileAndLine_data() {
    QTest::addColumn<QString>("text");
    QTest::addColumn<QString>("error");
    QTest::newRow("unbalanced brace") << "float a;\n}\n"
                                      << "t.glsl:2: unbalanced '}'";
    QTest::newRow("missing end") << "float a;\n\nvoid f() {\n  a = 1.0f;\n"
                                 << "t.glsl:3: declaration without its end";
    QTest::newRow("missing semicolon") << "float a"
                                       << "t.glsl:1: declaration without its end";
    QTest::newRow("unterminated comment") << "float a;\n/* never\nclosed"
                                          << "t.glsl:2: unterminated comment";
}

void GlslUnitTest::splitErrorsNameFileAndLine() {
    QFETCH(QString, text);
    QFETCH(QString, error);
    const Result<std::vector<GlslItem>> items = splitItems(text.toStdString(), 1, "t.glsl");
    QVERIFY(!items.ok());
    QVERIFY2(QString::fromStdString(items.error().message).startsWith(error),
             items.error().message.c_str());
}

void GlslUnitTest::reachability_data() {
    QTest::addColumn<QString>("text");
    QTest::addColumn<QString>("kept"); // names of the kept items, in order
    // Referenced, declared nowhere (sorted): uniforms and built-ins the generator declares,
    // and keywords and locals, which it ignores.
    QTest::addColumn<QString>("external");
    QTest::newRow("unused function dropped")
        << "float f() { return 1.0f; }\nfloat g() { return 2.0f; }\nvoid main() { g(); }"
        << "g|main"
        << "float,return,void";
    QTest::newRow("second name of a declaration reaches it")
        << "int a, b;\nint c;\nvoid main() { b = 1; }"
        << "a,b|main"
        << "int,void";
    QTest::newRow("chains and order kept")
        << "float h() { return pxU; }\nfloat g() { return h(); }\nvoid main() { g(); }"
        << "h|g|main"
        << "float,pxU,return,void";
    QTest::newRow("struct and define reached through a function")
        << "#define PX_N 4\nstruct S { float x; };\nS make() { S s; s.x = float(PX_N); "
           "return s; }\nvoid main() { make(); }"
        << "PX_N|S|make|main"
        << "float,return,s,struct,void,x";
    QTest::newRow("no main") << "float f() { return 1.0f; }"
                             << ""
                             << "main";
}

void GlslUnitTest::reachability() {
    QFETCH(QString, text);
    QFETCH(QString, kept);
    QFETCH(QString, external);
    const Result<std::vector<GlslItem>> items = splitItems(text.toStdString(), 1, "t.glsl");
    QVERIFY2(items.ok(), items ? "" : items.error().message.c_str());
    std::set<std::string> outside;
    const std::vector<const GlslItem*> reached = reachableItems(*items, {"main"}, outside);
    std::vector<GlslItem> copies;
    copies.reserve(reached.size());
    for (const GlslItem* item : reached)
        copies.push_back(*item);
    QCOMPARE(namesOf(copies), kept);
    QCOMPARE(joined(outside), external);
}

QTEST_APPLESS_MAIN(GlslUnitTest)
#include "GlslUnitTest.moc"

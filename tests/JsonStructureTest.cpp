// The shape check made before any JSON parser sees a text (core/json/JsonStructure.h): nesting bounded,
// duplicate keys named with their JSON path, strings and escapes read as JSON reads them, and
// text that is not JSON left to the parser. Also the files that go through it: a project with a
// key twice, and one nested past the bound, are refused naming the line and the key.

#include "core/json/JsonStructure.h"
#include "core/project/Project.h"

#include "TestSupport.h"

#include <QFile>
#include <QTemporaryDir>
#include <QtTest/QTest>

using namespace facet;

class JsonStructureTest : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void structure_data();
    void structure();
    void deepTextIsScannedWithoutRecursion();
    void projectFilesAreChecked_data();
    void projectFilesAreChecked();
};

void JsonStructureTest::structure_data()
{
    QTest::addColumn<QByteArray>("text");
    QTest::addColumn<int>("maxDepth");
    QTest::addColumn<bool>("refuseDuplicates");
    QTest::addColumn<QString>("problem"); // empty: none

    const auto row
        = [](const char* name, const QByteArray& text, int depth, bool duplicates, const char* problem) {
              QTest::newRow(name) << text << depth << duplicates << QString::fromUtf8(problem);
          };
    row("empty object", "{}", 4, true, "");
    row("depth at the bound", "[[[[1]]]]", 4, true, "");
    row("one past the bound", "[[[[[1]]]]]", 4, true,
        "line 1, column 5: arrays and objects nest deeper than 4 levels");
    row("objects count as levels", "{\"a\":{\"b\":{\"c\":{\"d\":{}}}}}", 4, true,
        "line 1, column 21: arrays and objects nest deeper than 4 levels");
    row("the position counts lines", "{\n  \"a\": [\n    [[[]]]\n  ]\n}", 4, true,
        "line 3, column 7: arrays and objects nest deeper than 4 levels");
    row("brackets in strings are text", "[\"[[[[[[[[\", \"{{{{{{\"]", 2, true, "");
    row("an escaped quote does not end a string", "[\"\\\"[[[[[[\"]", 2, true, "");
    row("siblings do not add up", "[[1],[2],[3],[4],[5],[6]]", 2, true, "");
    row("duplicate key", "{\"a\": 1, \"b\": 2, \"a\": 3}", 8, true,
        "line 1, column 18: the key \"a\" appears twice in one object");
    row("duplicate key allowed", "{\"a\": 1, \"a\": 3}", 8, false, "");
    row("duplicate key, its path", "{\"materials\": [{\"name\": \"x\"}, {\"name\": \"y\", \"name\": \"z\"}]}",
        8, true, "line 1, column 45: materials[1]: the key \"name\" appears twice in one object");
    row("duplicate key, nested objects", "{\"view\": {\"camera\": {\"fov\": 1, \"fov\": 2}}}", 8, true,
        "line 1, column 32: view.camera: the key \"fov\" appears twice in one object");
    row("keys compared decoded", "{\"a\": 1, \"\\u0061\": 2}", 8, true,
        "line 1, column 10: the key \"a\" appears twice in one object");
    row("surrogate pair keys compared decoded", "{\"\xF0\x9F\x98\x80\": 1, \"\\ud83d\\ude00\": 2}", 8, true,
        "line 1, column 10: the key \"\xF0\x9F\x98\x80\" appears twice in one object");
    row("the same key in two objects", "{\"a\": {\"k\": 1}, \"b\": {\"k\": 2}}", 8, true, "");
    row("a value equal to a key", "{\"a\": \"a\", \"b\": \"a\"}", 8, true, "");
    row("a key equal to a string in an array", "{\"a\": [\"b\", \"b\"], \"b\": 1}", 8, true, "");
    row("columns count characters, not bytes", "{\"\xC3\xA9\": 1, \"\xC3\xA9\": 2}", 8, true,
        "line 1, column 10: the key \"\xC3\xA9\" appears twice in one object");
    row("not JSON: an unclosed string", "{\"a\": \"never closed", 8, true, "");
    row("not JSON: a stray closing bracket", "]]]]", 2, true, "");
    row("not JSON: a bad escape", "{\"\\u00zz\": 1, \"\\u00zz\": 1}", 8, true, "");
}

void JsonStructureTest::structure()
{
    QFETCH(QByteArray, text);
    QFETCH(int, maxDepth);
    QFETCH(bool, refuseDuplicates);
    QFETCH(QString, problem);
    const std::optional<std::string> found
        = jsonStructureProblem(std::string_view(text.constData(), std::size_t(text.size())),
            JsonStructureRules {maxDepth, refuseDuplicates});
    QCOMPARE(QString::fromStdString(found.value_or(std::string())), problem);
}

// 10 million levels: refused at the bound, and a text of that many closing brackets after a
// valid document is not a crash either (the scan holds no more than maxDepth frames).
void JsonStructureTest::deepTextIsScannedWithoutRecursion()
{
    const std::string deep = std::string(10'000'000, '[') + std::string(10'000'000, ']');
    const std::optional<std::string> found = jsonStructureProblem(deep);
    QVERIFY(found);
    QVERIFY2(found->find("deeper than 256 levels") != std::string::npos, found->c_str());
    QVERIFY(!jsonStructureProblem(std::string(256, '[') + std::string(256, ']')));
}

void JsonStructureTest::projectFilesAreChecked_data()
{
    QTest::addColumn<QByteArray>("insert"); // placed after the project's opening brace
    QTest::addColumn<QString>("message");
    QTest::newRow("a key twice") << QByteArray("\"format\": \"facet-project\",")
                                 << QStringLiteral("the key \"format\" appears twice in one object");
    QTest::newRow("nested 20 000 deep")
        << QByteArray("\"extras\": ") + QByteArray(20000, '[') + QByteArray(20000, ']') + ","
        << QStringLiteral("arrays and objects nest deeper than 256 levels");
}

void JsonStructureTest::projectFilesAreChecked()
{
    QFETCH(QByteArray, insert);
    QFETCH(QString, message);
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("p.json"));
    std::string error;
    QVERIFY2(Project::defaultProject().save(path.toStdString(), &error), error.c_str());
    QFile file(path);
    QVERIFY(file.open(QIODevice::ReadOnly));
    QByteArray text = file.readAll();
    file.close();
    text.insert(text.indexOf('{') + 1, insert);
    QVERIFY(file.open(QIODevice::WriteOnly | QIODevice::Truncate));
    file.write(text);
    file.close();
    const std::optional<Project> project = Project::load(path.toStdString(), &error);
    QVERIFY2(!project, "the project was read");
    const QString text2 = QString::fromStdString(error);
    // The second of the two keys is named: the project's own "format", further down.
    QVERIFY2(text2.contains(path) && text2.contains(QStringLiteral(", column ")) && text2.contains(message),
        error.c_str());
}

QTEST_GUILESS_MAIN(JsonStructureTest)
#include "JsonStructureTest.moc"

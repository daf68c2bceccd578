// Every facet command in a code block of README.md and docs/*.md runs and exits 0 (issue 30: the
// README's own wedge example exited 2). The lines are extracted from the files as they are, in
// order, and run one after another in one folder, as an artist copying them would; a line with a
// placeholder (an upper-case word such as PROJECT or ENV_DIR, brackets, alternatives "a | b", a
// shell variable) is a usage line, not an example, and is skipped. The examples' inputs are
// stand-ins made here: scifi-panel.json (a textured project, support/TestAssets), DamagedHelmet.glb
// (the showcase asset), and the CC0 maps studio, night and forest (the small CC0 map of
// tests/data/hdri under each name, through $FACET_ASSETS_DIR). New projects use the split sum
// (tests/CMakeLists.txt), so the sheets take seconds on llvmpipe.

#include "TestAssets.h"
#include "TestSupport.h"

#include <QDir>
#include <QDirIterator>
#include <QFile>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest/QTest>

#include <cstdio>

namespace {

struct Example {
    QString file; // relative to the source folder
    int line = 0;
    QString command; // "facet ..."
};

// A usage line rather than an example: a placeholder, brackets, alternatives or a variable.
bool isUsageLine(const QString& command)
{
    static const QRegularExpression placeholder(QStringLiteral("\\b[A-Z][A-Z0-9_]{2,}\\b"));
    return command.contains(QLatin1Char('[')) || command.contains(QLatin1Char('|'))
        || command.contains(QLatin1Char('$')) || command.contains(QLatin1Char('<'))
        || placeholder.match(command).hasMatch();
}

std::vector<Example> examplesIn(const QString& relative, int* usageLines)
{
    std::vector<Example> examples;
    QFile file(facet::test::sourceDir() + QLatin1Char('/') + relative);
    if (!file.open(QIODevice::ReadOnly))
        return examples;
    bool inBlock = false;
    int number = 0;
    for (const QByteArray& raw : file.readAll().split('\n')) {
        ++number;
        QString line = QString::fromUtf8(raw).trimmed();
        if (line.startsWith(QStringLiteral("```"))) {
            inBlock = !inBlock;
            continue;
        }
        if (line.startsWith(QStringLiteral("$ ")))
            line = line.mid(2);
        if (!inBlock || !line.startsWith(QStringLiteral("facet ")))
            continue;
        if (isUsageLine(line)) {
            ++*usageLines;
            continue;
        }
        examples.push_back({relative, number, line});
    }
    return examples;
}

} // namespace

class DocCommandsTest : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void initTestCase()
    {
        QVERIFY(m_work.isValid() && m_assets.isValid());
        // The stand-ins the examples name.
        const QString project = facet::test::writeTexturedProject(m_work.path());
        QVERIFY(!project.isEmpty());
        QVERIFY(QFile::copy(project, m_work.filePath(QStringLiteral("scifi-panel.json"))));
        QString error;
        QVERIFY2(
            facet::test::writeShowcaseAsset(m_work.filePath(QStringLiteral("DamagedHelmet.glb")), &error),
            qPrintable(error));
        QVERIFY(QDir().mkpath(m_assets.filePath(QStringLiteral("hdri"))));
        const QString map = facet::test::sourceDir() + QStringLiteral("/tests/data/hdri/studio.exr");
        for (const char* name : {"studio", "night", "forest"})
            QVERIFY(
                QFile::copy(map, m_assets.filePath(QStringLiteral("hdri/%1.exr").arg(QLatin1String(name)))));
    }

    void examplesRun_data()
    {
        QTest::addColumn<QString>("command");
        QStringList files {QStringLiteral("README.md")};
        QDirIterator docs(facet::test::sourceDir() + QStringLiteral("/docs"), {QStringLiteral("*.md")});
        while (docs.hasNext())
            files << QStringLiteral("docs/") + QFileInfo(docs.next()).fileName();
        files.sort();
        int usageLines = 0;
        std::size_t readme = 0;
        for (const QString& file : files)
            for (const Example& example : examplesIn(file, &usageLines)) {
                readme += file == QLatin1String("README.md") ? 1 : 0;
                QTest::newRow(qPrintable(QStringLiteral("%1:%2").arg(example.file).arg(example.line)))
                    << example.command;
            }
        std::printf("  %d usage lines skipped\n", usageLines);
        // The README's examples are there to be found: a change of their form must not skip them all.
        QVERIFY2(readme >= 9, qPrintable(QStringLiteral("%1 README examples found").arg(readme)));
    }

    void examplesRun()
    {
        QFETCH(QString, command);
        QProcess process;
        QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
        environment.remove(QStringLiteral("DISPLAY"));
        environment.remove(QStringLiteral("WAYLAND_DISPLAY"));
        environment.insert(QStringLiteral("FACET_ASSETS_DIR"), m_assets.path());
        process.setProcessEnvironment(environment);
        process.setWorkingDirectory(m_work.path());
        QStringList arguments = command.split(QLatin1Char(' '), Qt::SkipEmptyParts);
        arguments.removeFirst(); // "facet"
        process.start(QStringLiteral(FACET_EXECUTABLE), arguments);
        QVERIFY2(process.waitForFinished(300000), qPrintable(command + QStringLiteral(": did not finish")));
        const QString err = QString::fromUtf8(process.readAllStandardError());
        QVERIFY2(process.exitStatus() == QProcess::NormalExit && process.exitCode() == 0,
            qPrintable(QStringLiteral("%1: exit %2\n%3").arg(command).arg(process.exitCode()).arg(err)));
    }

private:
    QTemporaryDir m_work;
    QTemporaryDir m_assets;
};

QTEST_GUILESS_MAIN(DocCommandsTest)
#include "DocCommandsTest.moc"

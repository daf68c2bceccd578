// File > Export… (ui/dialogs/ExportDialog) as an artist uses it: the file list follows the
// template, material, size and bit-depth choices (a depth the format cannot hold disables Export
// and says why); Export writes the set and reports it; files already in the folder are replaced
// only when the artist agrees; a user template file is offered, a broken one named; the window's
// File menu has the action.

#include <QComboBox>
#include <QDir>
#include <QLineEdit>
#include <QMenu>
#include <QMenuBar>
#include <QPushButton>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QtTest/QTest>

#include "FullVolume.h"
#include "TestAssets.h"
#include "TestSupport.h"
#include "core/project/Project.h"
#include "ui/MainWindow.h"
#include "ui/dialogs/ExportDialog.h"

using namespace facet;

namespace {

Project loadProject(const QString& path)
{
    std::string error;
    std::optional<Project> project = Project::load(path.toStdString(), &error);
    if (!project)
        qFatal("%s", error.c_str());
    return *project;
}

void choose(QComboBox* box, const QVariant& data)
{
    const int index = box->findData(data);
    QVERIFY2(index >= 0, qPrintable(data.toString()));
    box->setCurrentIndex(index);
}

QStringList entries(const QString& folder)
{
    return QDir(folder).entryList(QDir::Files, QDir::Name);
}

} // namespace

class ExportDialogUiTest : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void initTestCase()
    {
        QCoreApplication::setOrganizationName(QStringLiteral("FacetTests"));
        QCoreApplication::setApplicationName(QStringLiteral("ExportDialogUiTest"));
        QVERIFY(m_dir.isValid());
        m_projectPath = test::writeTexturedProject(m_dir.path());
        QVERIFY(!m_projectPath.isEmpty());
    }

    void previewFollowsChoices()
    {
        ExportDialog dialog(loadProject(m_projectPath));
        auto* templates = dialog.findChild<QComboBox*>(QStringLiteral("exportTemplate"));
        auto* materials = dialog.findChild<QComboBox*>(QStringLiteral("exportMaterials"));
        auto* size = dialog.findChild<QComboBox*>(QStringLiteral("exportSize"));
        auto* depth = dialog.findChild<QComboBox*>(QStringLiteral("exportBitDepth"));
        auto* button = dialog.findChild<QPushButton*>(QStringLiteral("exportButton"));
        QVERIFY(templates && materials && size && depth && button);

        choose(templates, QStringLiteral("unreal"));
        QVERIFY2(dialog.preview().startsWith(
                     QStringLiteral("Brick Wall (Unreal Engine): 3 files\n  T_Brick_Wall_BC.png  32x16")),
            qPrintable(dialog.preview()));
        QVERIFY(!dialog.preview().contains(QStringLiteral("Steel")));
        choose(materials, -1);
        QVERIFY(dialog.preview().contains(QStringLiteral("  T_Steel_ORM.png  8x8"))
            && dialog.preview().contains(QStringLiteral("  T_Gold_BC.png  1x1")));
        choose(size, 1024);
        QVERIFY2(dialog.preview().contains(QStringLiteral("  T_Brick_Wall_N.png  1024x512")),
            qPrintable(dialog.preview()));
        choose(templates, QStringLiteral("unity-hdrp"));
        QVERIFY(dialog.preview().contains(
            QStringLiteral("Brick_Wall_MaskMap.png  1024x512  RGBA 8-bit linear: R metallic, G occlusion")));
        QVERIFY(button->isEnabled());
        choose(depth, 32);
        QVERIFY2(dialog.preview().contains(QStringLiteral("cannot hold 32-bit channels")),
            qPrintable(dialog.preview()));
        QVERIFY(!button->isEnabled());
        choose(depth, 16);
        QVERIFY(dialog.preview().contains(QStringLiteral("RGBA 16-bit")));
        QVERIFY(button->isEnabled());
    }

    void exportsAndAsksBeforeReplacing()
    {
        QTemporaryDir out;
        ExportDialog dialog(loadProject(m_projectPath));
        choose(dialog.findChild<QComboBox*>(QStringLiteral("exportTemplate")), QStringLiteral("godot"));
        choose(dialog.findChild<QComboBox*>(QStringLiteral("exportSize")), 0);
        choose(dialog.findChild<QComboBox*>(QStringLiteral("exportBitDepth")), 0);
        dialog.setFolder(out.path());
        QStringList asked;
        bool answer = false;
        dialog.setConfirmReplace([&](const QStringList& existing) {
            asked = existing;
            return answer;
        });
        QSignalSpy exported(&dialog, &ExportDialog::exported);
        QVERIFY2(dialog.exportNow(), qPrintable(dialog.message()));
        QCOMPARE(exported.count(), 1);
        QCOMPARE(dialog.message(),
            QStringLiteral("Exported 3 files to %1 (Godot 4 (ORMMaterial3D))")
                .arg(QDir::toNativeSeparators(out.path())));
        QCOMPARE(entries(out.path()),
            test::strings({"Brick_Wall_albedo.png", "Brick_Wall_normal.png", "Brick_Wall_orm.png"}));
        QVERIFY(asked.isEmpty());

        // Again: the artist is asked, says no, and nothing changes; then yes.
        const QString orm = out.filePath(QStringLiteral("Brick_Wall_orm.png"));
        QVERIFY(test::writeText(orm, "keep me"));
        QVERIFY(!dialog.exportNow());
        QCOMPARE(asked.size(), 3);
        QCOMPARE(dialog.message(), QStringLiteral("Export cancelled: nothing was replaced."));
        QCOMPARE(test::fileBytes(orm), QByteArray("keep me"));
        answer = true;
        QVERIFY2(dialog.exportNow(), qPrintable(dialog.message()));
        QVERIFY(test::fileBytes(orm).startsWith("\x89PNG"));
        QCOMPARE(exported.count(), 2);
    }

    // glTF from the dialog: the list names the asset and its files; Export writes a valid asset
    // with every material on the view's mesh.
    void exportsGltf_data()
    {
        QTest::addColumn<QString>("format");
        QTest::addColumn<QStringList>("files");
        QTest::newRow("gltf") << QStringLiteral("gltf")
                              << test::strings({"walls.bin", "walls.gltf", "walls_Brick_Wall_baseColor.png",
                                     "walls_Brick_Wall_normal.png",
                                     "walls_Brick_Wall_occlusionRoughnessMetallic.png",
                                     "walls_Steel_baseColor.png",
                                     "walls_Steel_occlusionRoughnessMetallic.png"});
        QTest::newRow("glb") << QStringLiteral("glb") << test::strings({"walls.glb"});
    }

    void exportsGltf()
    {
        QFETCH(QString, format);
        QFETCH(QStringList, files);
        QTemporaryDir out;
        ExportDialog dialog(loadProject(m_projectPath), QStringLiteral("walls"));
        dialog.setFolder(out.path());
        choose(dialog.findChild<QComboBox*>(QStringLiteral("exportSize")), 0);
        choose(dialog.findChild<QComboBox*>(QStringLiteral("exportBitDepth")), 0);
        choose(dialog.findChild<QComboBox*>(QStringLiteral("exportMaterials")), -1);
        choose(dialog.findChild<QComboBox*>(QStringLiteral("exportTemplate")), format);
        QVERIFY2(dialog.preview().startsWith(QStringLiteral("walls.%1 on the view's mesh:\n").arg(format)),
            qPrintable(dialog.preview()));
        QCOMPARE(dialog.preview().count(QStringLiteral("\n  ")), files.size());
        QVERIFY2(dialog.exportNow(), qPrintable(dialog.message()));
        QCOMPARE(entries(out.path()), files);
        FACET_REQUIRE_VALID_GLTF(out.filePath(QStringLiteral("walls.") + format));
    }

    void userTemplates()
    {
        ExportDialog dialog(loadProject(m_projectPath));
        const QString good = m_dir.filePath(QStringLiteral("studio-engine.json"));
        QVERIFY(test::writeText(good,
            R"({"format": "facet-export-template", "version": 1, "name": "Studio engine",
                "outputs": [{"map": "rough", "channels": ["roughness"], "bitDepth": 16}]})"));
        QVERIFY(dialog.useTemplateFile(good));
        QVERIFY2(dialog.preview().startsWith(QStringLiteral(
                     "Brick Wall (Studio engine): 1 files\n  Brick_Wall_rough.png  32x16  grey 16-bit")),
            qPrintable(dialog.preview()));
        const QString bad = m_dir.filePath(QStringLiteral("bad-engine.json"));
        QVERIFY(test::writeText(bad,
            R"({"format": "facet-export-template", "version": 1, "outputs": [{"map": "r", "channels": ["rough"]}]})"));
        QVERIFY(!dialog.useTemplateFile(bad));
        QVERIFY2(dialog.message().startsWith(
                     bad + QStringLiteral(": outputs[0].channels[0]: \"rough\" is not a source")),
            qPrintable(dialog.message()));
    }

    void fileMenuHasIt()
    {
        MainWindow window(nullptr, m_dir.filePath(QStringLiteral("recovery")));
        auto* action = window.findChild<QAction*>(QStringLiteral("exportAction"));
        QVERIFY(action);
        QCOMPARE(action->shortcut(), QKeySequence(Qt::CTRL | Qt::Key_E));
        auto* fileMenu = window.findChild<QMenu*>(QStringLiteral("fileMenu"));
        QVERIFY(fileMenu && fileMenu->actions().contains(action));
    }

private:
    QTemporaryDir m_dir;
    QString m_projectPath;
};

QTEST_MAIN(ExportDialogUiTest)
#include "ExportDialogUiTest.moc"

// Texture sets in the main window under Xvfb, driven as a user does: every way of putting a file
// in a slot (the slot's Open… dialog, a drop on the slot, several files or a folder dropped on the
// dock, the Assign Folder… dialog) reads the channel the file's packing convention gives that slot
// (core/material/MapNaming.h; its naming table is MapNamingTest's); assigning a set replaces the whole set
// in one undo step and says what it cleared; the dock's note goes when another project replaces
// the document (New, Open, recovery). Needs a display (Xvfb via with-display.sh).

#include "ui/MainWindow.h"
#include "ui/docks/MapSlotWidget.h"
#include "ui/docks/TextureMapsDock.h"
#include "ui/document/Document.h"
#include "ui/document/ProjectFileController.h"
#include "ui/viewport/SurfaceFormat.h"
#include "ui/viewport/ViewportWidget.h"

#include "TestSupport.h"

#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QDir>
#include <QElapsedTimer>
#include <QFileDialog>
#include <QImage>
#include <QLabel>
#include <QMimeData>
#include <QPushButton>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTimer>
#include <QUndoStack>
#include <QUrl>
#include <QtTest/QTest>

#include <memory>

using namespace facet;

Q_DECLARE_METATYPE(facet::MapSlot)
Q_DECLARE_METATYPE(facet::MapChannel)

namespace {

// A file with a distinct value in each channel (R 40, G 120, B 200, A 230), as a packed texture has.
bool writePacked(const QString& path)
{
    QImage image(QSize(8, 8), QImage::Format_ARGB32);
    image.fill(QColor(40, 120, 200, 230));
    return image.save(path);
}

QStringList makeFiles(const QString& folder, const QStringList& names)
{
    QDir().mkpath(folder);
    QStringList paths;
    for (const QString& name : names) {
        const QString path = QDir(folder).filePath(name);
        if (writePacked(path))
            paths.append(path);
    }
    return paths;
}

// Drags `urls` onto `target` and drops them there, as the desktop would.
bool dropUrls(QWidget* target, const QList<QUrl>& urls)
{
    QMimeData mime;
    mime.setUrls(urls);
    const QPoint pos = target->rect().center();
    QDragEnterEvent enter(pos, Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
    QCoreApplication::sendEvent(target, &enter);
    if (!enter.isAccepted())
        return false;
    QDropEvent drop(QPointF(pos), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
    QCoreApplication::sendEvent(target, &drop);
    return drop.isAccepted();
}

// Clicks `button`, which opens a file dialog, and answers the dialog with `path` (a file for an
// open dialog, a folder for a folder dialog) the way a user would: choose it, press Open.
bool clickAndAnswerFileDialog(QPushButton* button, const QString& path)
{
    // Polls for the dialog for as long as the click is under way (a loaded machine may take
    // seconds to show it); a modal widget that is not the file dialog, still there after 30 s, is
    // rejected so that the test fails instead of hanging.
    bool answered = false;
    QElapsedTimer clock;
    clock.start();
    QTimer poll;
    poll.setInterval(50);
    QObject::connect(&poll, &QTimer::timeout, [&] {
        QWidget* modal = QApplication::activeModalWidget();
        auto* dialog = qobject_cast<QFileDialog*>(modal);
        if (!dialog) {
            if (auto* other = qobject_cast<QDialog*>(modal); other && clock.elapsed() > 30000)
                other->reject();
            return;
        }
        poll.stop();
        if (dialog->fileMode() == QFileDialog::Directory)
            dialog->setDirectory(path); // nothing typed: the dialog answers its directory
        else
            dialog->selectFile(path);
        answered = true;
        static_cast<QDialog*>(dialog)->accept(); // QFileDialog::accept, as the Open button does
    });
    poll.start();
    QTest::mouseClick(button, Qt::LeftButton);
    return answered;
}

QString describe(const MaterialMap& map)
{
    return QStringLiteral("%1: channel %2 invert %3 flip %4")
        .arg(QString::fromStdString(map.path), QString::fromLatin1(toString(map.channel)))
        .arg(map.invert)
        .arg(map.flipGreen);
}

} // namespace

class TextureSetUiTest : public QObject {
    Q_OBJECT
public:
    static void initMain()
    {
        QStandardPaths::setTestModeEnabled(true);
        // Qt's own file dialog (not the desktop's), which the test can answer.
        QCoreApplication::setAttribute(Qt::AA_DontUseNativeDialogs);
        installViewportSurfaceFormat();
    }

private Q_SLOTS:
    void initTestCase();
    void cleanupTestCase();
    void init();
    void slotReadsItsChannelOfAPackedFile_data();
    void slotReadsItsChannelOfAPackedFile();
    void dockAssignsPackedChannels_data();
    void dockAssignsPackedChannels();
    void assigningASetReplacesTheWholeSet();
    void oneFileDroppedOnTheDockAddsToTheSet();
    void noteGoesWithTheProject_data();
    void noteGoesWithTheProject();
    void uvSetAndWrapAreEditedAndUndone_data();
    void uvSetAndWrapAreEditedAndUndone();

private:
    QTemporaryDir m_dir;
    std::unique_ptr<MainWindow> m_window;
    Document* m_document = nullptr;
    TextureMapsDock* m_dock = nullptr;
};

void TextureSetUiTest::initTestCase()
{
    QCoreApplication::setOrganizationName(QStringLiteral("FacetTests"));
    QVERIFY(m_dir.isValid());
    m_window = std::make_unique<MainWindow>(nullptr, m_dir.filePath(QStringLiteral("recovery")));
    m_document = m_window->document();
    m_dock = m_window->textureMapsDock();
    QSignalSpy rendered(m_window->viewport(), &ViewportWidget::frameRendered);
    m_window->show();
    QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
    m_window->resetLayout();
    QVERIFY(rendered.count() > 0 || rendered.wait(60000));
    m_window->projectFiles()->setUnsavedChangesAnswer(QMessageBox::Discard);
    m_window->projectFiles()->setErrorDialogsEnabled(false);
}

void TextureSetUiTest::cleanupTestCase()
{
    m_document->newProject();
    m_window.reset();
}

void TextureSetUiTest::init()
{
    m_document->newProject(); // every test starts without textures
    m_dock->raise();
}

void TextureSetUiTest::slotReadsItsChannelOfAPackedFile_data()
{
    QTest::addColumn<bool>("drop"); // false: the slot's Open… button and its file dialog
    QTest::addColumn<QString>("file");
    QTest::addColumn<MapSlot>("slot");
    QTest::addColumn<MapChannel>("channel");
    QTest::addColumn<bool>("invert");
    QTest::addColumn<QString>("note"); // what the status bar adds about the read

    using S = MapSlot;
    using C = MapChannel;
    for (const bool drop : {false, true}) {
        const char* how = drop ? "drop" : "open";
        QTest::addRow("%s ORM on metallic", how)
            << drop << "set_orm.png" << S::Metallic << C::B << false << "(ORM, blue)";
        QTest::addRow("%s ORM on roughness", how)
            << drop << "set_orm.png" << S::Roughness << C::G << false << "(ORM, green)";
        QTest::addRow("%s ORM on occlusion", how)
            << drop << "set_orm.png" << S::Occlusion << C::R << false << "(ORM, red)";
        QTest::addRow("%s glTF on metallic", how) << drop << "Default_metalRoughness.png" << S::Metallic
                                                  << C::B << false << "(glTF metallic-roughness, blue)";
        QTest::addRow("%s mask map on roughness", how) << drop << "rock_MaskMap.png" << S::Roughness << C::A
                                                       << true << "(Unity mask map, alpha, inverted)";
        QTest::addRow("%s mask map on occlusion", how)
            << drop << "rock_MaskMap.png" << S::Occlusion << C::G << false << "(Unity mask map, green)";
        QTest::addRow("%s Unreal MRA on occlusion", how)
            << drop << "T_Crate_MRA.png" << S::Occlusion << C::B << false << "(MRA, blue)";
        QTest::addRow("%s roughness file", how)
            << drop << "wood_roughness.png" << S::Roughness << C::R << false << "";
        QTest::addRow("%s gloss on roughness", how)
            << drop << "wood_gloss.png" << S::Roughness << C::R << true << "(inverted)";
    }
}

void TextureSetUiTest::slotReadsItsChannelOfAPackedFile()
{
    QFETCH(bool, drop);
    QFETCH(QString, file);
    QFETCH(MapSlot, slot);
    QFETCH(MapChannel, channel);
    QFETCH(bool, invert);
    QFETCH(QString, note);
    const QString path = m_dir.filePath(QStringLiteral("single/") + file);
    QCOMPARE(makeFiles(QFileInfo(path).path(), {file}).size(), 1);
    MapSlotWidget* widget = m_dock->slotWidget(slot);
    const int steps = m_document->undoStack()->index();

    if (drop) {
        QVERIFY(dropUrls(widget, {QUrl::fromLocalFile(path)}));
    } else {
        auto* open = widget->findChild<QPushButton*>(
            QStringLiteral("mapOpenButton_%1").arg(QString::fromLatin1(toString(slot))));
        QVERIFY(open);
        QVERIFY(clickAndAnswerFileDialog(open, path));
    }

    const MaterialMap& map = m_document->project().material().map(slot);
    QVERIFY2(map.path == path.toStdString() && map.channel == channel && map.invert == invert,
        qPrintable(describe(map)));
    QCOMPARE(m_document->undoStack()->index(), steps + 1);
    // The slot's controls show the read, so the user sees it and can change it.
    auto* channelCombo = widget->findChild<QComboBox*>(
        QStringLiteral("mapChannel_%1").arg(QString::fromLatin1(toString(slot))));
    QVERIFY(channelCombo);
    QCOMPARE(MapChannel(channelCombo->currentData().toInt()), channel);
    const QString message = m_window->statusMessage();
    QVERIFY2(message.contains(file) && (note.isEmpty() ? !message.contains(u'(') : message.contains(note)),
        qPrintable(message));
}

void TextureSetUiTest::dockAssignsPackedChannels_data()
{
    QTest::addColumn<QString>("how"); // "files": several files dropped, "folder": a folder dropped,
                                      // "button": Assign Folder… and its dialog
    QTest::addColumn<QStringList>("files");
    QTest::addColumn<QString>("expected"); // "<slot>:<channel>[!]" per slot, '!' inverted, '^' DirectX
    const QStringList orm = {QStringLiteral("metal_basecolor.png"), QStringLiteral("metal_normal.png"),
        QStringLiteral("metal_orm.png"), QStringLiteral("metal_emissive.png")};
    const QStringList mask = {QStringLiteral("Rock_BaseColor.png"), QStringLiteral("Rock_Normal.png"),
        QStringLiteral("Rock_MaskMap.png"), QStringLiteral("Rock_Emission.png")};
    const QStringList unreal = {QStringLiteral("T_Crate_BC.png"), QStringLiteral("T_Crate_N.png"),
        QStringLiteral("T_Crate_ORM.png"), QStringLiteral("T_Crate_E.png")};
    const QString ormExpected
        = QStringLiteral("baseColor:rgb normal:rgb metallic:b roughness:g occlusion:r emissive:rgb");
    const QString maskExpected
        = QStringLiteral("baseColor:rgb normal:rgb metallic:r roughness:a! occlusion:g emissive:rgb");
    const QString unrealExpected
        = QStringLiteral("baseColor:rgb normal:rgb^ metallic:b roughness:g occlusion:r emissive:rgb");
    for (const char* how : {"files", "folder", "button"}) {
        QTest::addRow("%s ORM", how) << QString::fromLatin1(how) << orm << ormExpected;
        QTest::addRow("%s mask map", how) << QString::fromLatin1(how) << mask << maskExpected;
        QTest::addRow("%s Unreal", how) << QString::fromLatin1(how) << unreal << unrealExpected;
    }
}

void TextureSetUiTest::dockAssignsPackedChannels()
{
    QFETCH(QString, how);
    QFETCH(QStringList, files);
    QFETCH(QString, expected);
    const QString folder = m_dir.filePath(
        QStringLiteral("dock-") + QString::fromLatin1(QTest::currentDataTag()).replace(u' ', u'-'));
    const QStringList paths = makeFiles(folder, files);
    QCOMPARE(paths.size(), files.size());
    const int steps = m_document->undoStack()->index();

    if (how == QLatin1String("files")) {
        QList<QUrl> urls;
        for (const QString& path : paths)
            urls.append(QUrl::fromLocalFile(path));
        QVERIFY(dropUrls(m_dock, urls));
    } else if (how == QLatin1String("folder")) {
        QVERIFY(dropUrls(m_dock, {QUrl::fromLocalFile(folder)}));
    } else {
        auto* button = m_dock->findChild<QPushButton*>(QStringLiteral("assignFolderButton"));
        QVERIFY(button);
        QVERIFY(clickAndAnswerFileDialog(button, folder));
    }

    QStringList got;
    for (MapSlot slot : kAllMapSlots) {
        const MaterialMap& map = m_document->project().material().map(slot);
        if (lobeOf(slot) != MaterialLobe::Core) {
            QVERIFY2(!map.hasTexture(), toString(slot)); // no coat file in these sets
            continue;
        }
        QVERIFY2(map.hasTexture(), toString(slot));
        QString entry = QStringLiteral("%1:%2").arg(
            QString::fromLatin1(toString(slot)), QString::fromLatin1(toString(map.channel)));
        if (map.invert)
            entry += u'!';
        if (map.flipGreen)
            entry += u'^';
        got.append(entry);
    }
    QCOMPARE(got.join(u' '), expected);
    QCOMPARE(m_document->undoStack()->index(), steps + 1);
    QCOMPARE(m_document->undoStack()->undoText(), QStringLiteral("Assign Maps"));
    QVERIFY2(m_dock->lastMessage().startsWith(QStringLiteral("Assigned 6 maps")),
        qPrintable(m_dock->lastMessage()));
}

void TextureSetUiTest::assigningASetReplacesTheWholeSet()
{
    // Set A: fourteen separate maps, a clear coat's three, a sheen's two, a specular colour, an
    // anisotropy direction map and a film's packed strength and thickness among them, through Assign Folder… (the specular strength has no file name of its own: a bare
    // "specular" is a specular-glossiness map, core/material/MapNaming.h).
    const QString a = m_dir.filePath(QStringLiteral("replace/a"));
    makeFiles(a,
        {QStringLiteral("a_basecolor.png"), QStringLiteral("a_normal.png"), QStringLiteral("a_metallic.png"),
            QStringLiteral("a_roughness.png"), QStringLiteral("a_ao.png"), QStringLiteral("a_emissive.png"),
            QStringLiteral("a_clearcoat.png"), QStringLiteral("a_clearcoat_roughness.png"),
            QStringLiteral("a_clearcoat_normal.png"), QStringLiteral("a_sheen.png"),
            QStringLiteral("a_sheen_roughness.png"), QStringLiteral("a_specular_color.png"),
            QStringLiteral("a_anisotropy.png"), QStringLiteral("a_iridescence.png")});
    auto* button = m_dock->findChild<QPushButton*>(QStringLiteral("assignFolderButton"));
    QVERIFY(button);
    QVERIFY(clickAndAnswerFileDialog(button, a));
    const Material setA = m_document->project().material();
    for (MapSlot slot : kAllMapSlots)
        QVERIFY2(setA.map(slot).hasTexture() == (slot != MapSlot::Specular), toString(slot));
    QVERIFY(setA.hasSpecular()); // the colour texture modulates the layer
    QCOMPARE(setA.metallic(), 1.0); // the texture shows as painted
    QCOMPARE(setA.clearcoat(), 1.0); // a coat texture turns the coat on, as painted
    QCOMPARE(setA.clearcoatRoughness(), 1.0);
    QVERIFY(m_dock->lobeSlots(MaterialLobe::Clearcoat)->isVisibleTo(m_dock));
    QCOMPARE(setA.sheenColor(), glm::dvec3(1.0)); // a sheen texture turns a white sheen on
    QCOMPARE(setA.sheenRoughness(), 1.0);
    QVERIFY(m_dock->lobeSlots(MaterialLobe::Sheen)->isVisibleTo(m_dock));
    QCOMPARE(setA.anisotropy(), 1.0); // a direction map turns anisotropy on, shaped by the map
    QVERIFY(m_dock->lobeSlots(MaterialLobe::Anisotropy)->isVisibleTo(m_dock));
    QCOMPARE(setA.iridescence(), 1.0); // a film texture turns a full film on, shaped by the map
    QCOMPARE(setA.map(MapSlot::Iridescence).path, setA.map(MapSlot::IridescenceThickness).path); // R and G
    QVERIFY(m_dock->lobeSlots(MaterialLobe::Iridescence)->isVisibleTo(m_dock));
    const int steps = m_document->undoStack()->index();
    QSignalSpy rendered(m_window->viewport(), &ViewportWidget::frameRendered);

    // Set B has only a base colour and a roughness map: nothing of A may stay in the other slots.
    const QString b = m_dir.filePath(QStringLiteral("replace/b"));
    makeFiles(b, {QStringLiteral("b_basecolor.png"), QStringLiteral("b_roughness.png")});
    QVERIFY(clickAndAnswerFileDialog(button, b));

    const Material& setB = m_document->project().material();
    QCOMPARE(QFileInfo(QString::fromStdString(setB.map(MapSlot::BaseColor).path)).fileName(),
        QStringLiteral("b_basecolor.png"));
    QCOMPARE(QFileInfo(QString::fromStdString(setB.map(MapSlot::Roughness).path)).fileName(),
        QStringLiteral("b_roughness.png"));
    for (MapSlot slot : {MapSlot::Normal, MapSlot::Metallic, MapSlot::Occlusion, MapSlot::Emissive,
             MapSlot::Clearcoat, MapSlot::ClearcoatRoughness, MapSlot::ClearcoatNormal, MapSlot::SheenColor,
             MapSlot::SheenRoughness, MapSlot::SpecularColor, MapSlot::Anisotropy, MapSlot::Iridescence,
             MapSlot::IridescenceThickness})
        QVERIFY2(!setB.map(slot).hasTexture(), toString(slot));
    QVERIFY(!setB.hasIridescence());
    QVERIFY(!m_dock->lobeSlots(MaterialLobe::Iridescence)->isVisibleTo(m_dock));
    QVERIFY(!setB.hasAnisotropy());
    QVERIFY(!m_dock->lobeSlots(MaterialLobe::Anisotropy)->isVisibleTo(m_dock));
    QVERIFY(!setB.hasSpecular()); // back to the core's layer
    QCOMPARE(setB.metallic(), 0.0); // a dielectric, not A's metallic factor of 1 alone
    QVERIFY(!setB.hasClearcoat()); // and no coat: A's came with A's coat maps
    QVERIFY(!m_dock->lobeSlots(MaterialLobe::Clearcoat)->isVisibleTo(m_dock));
    QVERIFY(!setB.hasSheen());
    QVERIFY(!m_dock->lobeSlots(MaterialLobe::Sheen)->isVisibleTo(m_dock));
    QCOMPARE(m_document->undoStack()->index(), steps + 1); // one step
    const QString message = m_dock->lastMessage();
    QVERIFY2(message.startsWith(QStringLiteral("Assigned 2 maps")), qPrintable(message));
    QVERIFY2(message.contains(QStringLiteral(
                 "cleared (not in this set): Normal, Metallic (now 0), Ambient "
                 "Occlusion, Emissive, Clearcoat (no coat now), Clearcoat Roughness, "
                 "Clearcoat Normal, Sheen Colour (no sheen now), Sheen Roughness, Specular Colour, "
                 "Anisotropy (isotropic now), Iridescence (no film now), Iridescence Thickness")),
        qPrintable(message));
    QCOMPARE(m_window->statusMessage(), message);
    // The slots say so too.
    QCOMPARE(m_dock->slotWidget(MapSlot::Metallic)->fileLabel()->text(),
        QStringLiteral("No file: the value below"));
    QVERIFY(rendered.count() > 0 || rendered.wait(30000));

    // One undo brings set A back whole; redo B again.
    m_document->undoStack()->undo();
    QCOMPARE(m_document->project().material(), setA);
    m_document->undoStack()->redo();
    QVERIFY(!m_document->project().material().map(MapSlot::Normal).hasTexture());
}

void TextureSetUiTest::oneFileDroppedOnTheDockAddsToTheSet()
{
    const QString a = m_dir.filePath(QStringLiteral("add/a"));
    const QStringList set = makeFiles(a, {QStringLiteral("a_basecolor.png"), QStringLiteral("a_normal.png")});
    QVERIFY(dropUrls(m_dock, {QUrl::fromLocalFile(a)}));
    const QString extra
        = makeFiles(m_dir.filePath(QStringLiteral("add/b")), {QStringLiteral("b_orm.png")}).value(0);
    QVERIFY(dropUrls(m_dock, {QUrl::fromLocalFile(extra)}));
    const Material& material = m_document->project().material();
    QCOMPARE(QString::fromStdString(material.map(MapSlot::BaseColor).path), set[0]);
    QCOMPARE(QString::fromStdString(material.map(MapSlot::Normal).path), set[1]);
    QCOMPARE(QString::fromStdString(material.map(MapSlot::Metallic).path), extra);
    QVERIFY2(!m_dock->lastMessage().contains(QStringLiteral("cleared")), qPrintable(m_dock->lastMessage()));
}

void TextureSetUiTest::noteGoesWithTheProject_data()
{
    QTest::addColumn<QString>("replacement");
    QTest::newRow("File > New") << "new";
    QTest::newRow("open") << "open";
    QTest::newRow("recovery") << "recovery";
}

void TextureSetUiTest::noteGoesWithTheProject()
{
    QFETCH(QString, replacement);
    // A project to open and a recovery file to recover, made before the note.
    const QString project = m_dir.filePath(QStringLiteral("other.json"));
    QString error;
    QVERIFY2(m_document->saveAs(project, &error), qPrintable(error));
    const QString recovery = m_dir.filePath(QStringLiteral("other.recovery.json"));
    QVERIFY2(m_document->writeRecoveryFile(recovery, &error), qPrintable(error));

    const QString folder = m_dir.filePath(QStringLiteral("note"));
    makeFiles(folder,
        {QStringLiteral("n_basecolor.png"), QStringLiteral("n_normal.png"), QStringLiteral("n_orm.png")});
    QVERIFY(dropUrls(m_dock, {QUrl::fromLocalFile(folder)}));
    auto* label = m_dock->findChild<QLabel*>(QStringLiteral("textureMapsMessage"));
    QVERIFY(label);
    QVERIFY(label->isVisible());
    QVERIFY(m_dock->lastMessage().startsWith(QStringLiteral("Assigned 5 maps")));

    if (replacement == QLatin1String("new")) {
        auto* action = m_window->findChild<QAction*>(QStringLiteral("newAction"));
        QVERIFY(action);
        action->trigger();
    } else if (replacement == QLatin1String("open")) {
        QVERIFY(m_window->projectFiles()->openFile(project));
    } else {
        QVERIFY2(m_document->recover(recovery, &error), qPrintable(error));
    }

    QVERIFY(!m_document->project().material().map(MapSlot::BaseColor).hasTexture());
    QVERIFY2(m_dock->lastMessage().isEmpty(), qPrintable(m_dock->lastMessage()));
    QVERIFY(!label->isVisible());
}

void TextureSetUiTest::uvSetAndWrapAreEditedAndUndone_data()
{
    QTest::addColumn<MapSlot>("slot");
    for (const MapSlot slot : {MapSlot::BaseColor, MapSlot::Normal, MapSlot::Occlusion, MapSlot::Emissive})
        QTest::newRow(toString(slot)) << slot;
}

// Issue 29: each map's UV set and wrap are fields of the slot, each one undo step; a file's mixed
// wrap pair shows as one more entry until the artist picks one wrap for both.
void TextureSetUiTest::uvSetAndWrapAreEditedAndUndone()
{
    QFETCH(MapSlot, slot);
    const QString key = QString::fromLatin1(toString(slot));
    const QString path = m_dir.filePath(QStringLiteral("wrap/wood_basecolor.png"));
    QCOMPARE(makeFiles(QFileInfo(path).path(), {QStringLiteral("wood_basecolor.png")}).size(), 1);
    MapSlotWidget* widget = m_dock->slotWidget(slot);
    QVERIFY(dropUrls(widget, {QUrl::fromLocalFile(path)}));
    auto* uvSet = widget->findChild<QComboBox*>(QStringLiteral("mapTexCoord_%1").arg(key));
    auto* wrap = widget->findChild<QComboBox*>(QStringLiteral("mapWrap_%1").arg(key));
    QVERIFY(uvSet && wrap && uvSet->isEnabled() && wrap->isEnabled());
    const auto map = [&] { return m_document->project().material().map(slot); };
    const int steps = m_document->undoStack()->index();

    uvSet->setCurrentIndex(uvSet->findData(1));
    Q_EMIT uvSet->activated(uvSet->currentIndex());
    QCOMPARE(map().texCoord, 1);
    wrap->setCurrentIndex(wrap->findData(int(TextureWrap::MirroredRepeat)));
    Q_EMIT wrap->activated(wrap->currentIndex());
    QCOMPARE(map().sampler.wrapS, TextureWrap::MirroredRepeat);
    QCOMPARE(map().sampler.wrapT, TextureWrap::MirroredRepeat);
    QCOMPARE(m_document->undoStack()->index(), steps + 2);
    m_document->undoStack()->undo();
    QCOMPARE(map().sampler.wrapS, TextureWrap::Repeat);
    QCOMPARE(wrap->currentData().toInt(), int(TextureWrap::Repeat));
    m_document->undoStack()->undo();
    QCOMPARE(map().texCoord, 0);
    QCOMPARE(uvSet->currentData().toInt(), 0);

    // A mixed pair (from a file): shown as it is, replaced by a choice for both axes.
    Material material = m_document->project().material();
    material.map(slot).sampler.wrapS = TextureWrap::ClampToEdge;
    m_document->setMaterial(material, QStringLiteral("Mixed"));
    QCOMPARE(wrap->count(), 4);
    QCOMPARE(wrap->currentText(), QStringLiteral("U clamp, V repeat"));
    wrap->setCurrentIndex(wrap->findData(int(TextureWrap::ClampToEdge)));
    Q_EMIT wrap->activated(wrap->currentIndex());
    QCOMPARE(map().sampler.wrapT, TextureWrap::ClampToEdge);
    QCOMPARE(wrap->count(), 3);
}

QTEST_MAIN(TextureSetUiTest)
#include "TextureSetUiTest.moc"

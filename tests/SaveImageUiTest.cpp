// File > Save Image… (MainWindow::saveImageTo) as an artist uses it: the single view as a PNG
// (what it shows: the same display transform as the window's frame) and as a linear EXR (the scene
// radiance under it, HDR values a PNG cannot hold), each at the view's full size; the compare grid
// as shown (PNG; an EXR of it refused with why); a format it does not write and a full disk
// refused with the file named, nothing left behind. A still at a chosen size (larger than the
// view, odd, tall), with a transparent background or not, and one too large refused; a turntable
// (File > Save Turntable…, ui/dialogs/ImageSaver) as frames of each subject and format, stopped when asked,
// as a video (with ffmpeg; without it the message), and the dialog remembering its choices.

#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QLabel>
#include <QPushButton>
#include <QSettings>
#include <QSpinBox>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest/QTest>

#include <OpenImageIO/imageio.h>

#include <cmath>

#include "FullVolume.h"
#include "TestSupport.h"
#include "core/image/Image.h"
#include "render/Turntable.h"
#include "ui/MainWindow.h"
#include "ui/compare/CompareView.h"
#include "ui/dialogs/ImageSaver.h"
#include "ui/dialogs/SaveImageDialog.h"
#include "ui/document/Document.h"
#include "ui/viewport/SceneController.h"
#include "ui/viewport/SurfaceFormat.h"
#include "ui/viewport/ViewportWidget.h"

using namespace facet;
using facet::test::FullVolume;

class SaveImageUiTest : public QObject {
    Q_OBJECT
public:
    static void initMain()
    {
        FullVolume::isolateMounts();
        QStandardPaths::setTestModeEnabled(true); // its settings are the test's own
        installViewportSurfaceFormat();
    }

private Q_SLOTS:
    void initTestCase()
    {
        QCoreApplication::setOrganizationName(QStringLiteral("FacetTests"));
        QSettings().clear();
        QVERIFY(m_dir.isValid());
        m_window = std::make_unique<MainWindow>(nullptr, m_dir.filePath(QStringLiteral("recovery")));
        m_window->resize(900, 640);
        m_window->show();
        QVERIFY(QTest::qWaitForWindowExposed(m_window.get()));
        // The first full frame (not a preview, the lighting ready).
        QTRY_VERIFY_WITH_TIMEOUT(
            m_window->viewport()->frameCount() > 0 && !m_window->viewport()->isPreviewing(), 60000);
        QTest::qWait(500);
    }

    void cleanupTestCase() { m_window.reset(); }

    void singleViewPngIsWhatItShows()
    {
        const QString path = m_dir.filePath(QStringLiteral("view.png"));
        QString error;
        QVERIFY2(m_window->saveImageTo(path, &error), qPrintable(error));
        QCOMPARE(m_window->statusMessage(), QStringLiteral("Saved %1").arg(QDir::toNativeSeparators(path)));
        const QImage saved(path);
        ViewportWidget* view = m_window->viewport();
        const QImage shown = view->grabFramebuffer().convertToFormat(QImage::Format_RGB888);
        QCOMPARE(saved.size(), shown.size());
        // The default project's sphere in the studio: the same transform, so the same pixels up to
        // the frame's own rounding (the window's frame may still be anti-aliasing differently at
        // the silhouette: compare the mean).
        double difference = 0.0;
        const QImage savedRgb = saved.convertToFormat(QImage::Format_RGB888);
        for (int y = 0; y < saved.height(); ++y)
            for (int x = 0; x < saved.width(); ++x) {
                const QColor a = savedRgb.pixelColor(x, y);
                const QColor b = shown.pixelColor(x, y);
                difference += std::abs(a.red() - b.red()) + std::abs(a.green() - b.green())
                    + std::abs(a.blue() - b.blue());
            }
        difference /= 3.0 * saved.width() * saved.height();
        qInfo("PNG vs the window's frame: mean difference %.3f of 255", difference);
        QVERIFY2(difference < 1.0, qPrintable(QString::number(difference)));
    }

    void singleViewExrIsLinearRadiance()
    {
        const QString path = m_dir.filePath(QStringLiteral("view.exr"));
        QString error;
        QVERIFY2(m_window->saveImageTo(path, &error), qPrintable(error));
        auto input = OIIO::ImageInput::open(path.toStdString());
        QVERIFY(input);
        QCOMPARE(input->spec().format, OIIO::TypeDesc(OIIO::TypeDesc::HALF));
        const QSize size = m_window->viewport()->grabFramebuffer().size();
        QCOMPARE(input->spec().width, size.width());
        QCOMPARE(input->spec().height, size.height());
        std::string problem;
        const std::optional<Image> image = Image::load(path.toStdString(), &problem);
        QVERIFY2(image, problem.c_str());
        // Scene radiance: the studio's lights reflected by the glossy sphere exceed 1 somewhere,
        // which a display-referred image never does.
        float brightest = 0.0f;
        for (std::size_t i = 0; i < image->pixelCount(); ++i)
            brightest = std::max({brightest, image->data()[i].r, image->data()[i].g, image->data()[i].b});
        qInfo("EXR: brightest value %.2f", brightest);
        QVERIFY(brightest > 1.0f);
    }

    void refusals()
    {
        QString error;
        const QString jpeg = m_dir.filePath(QStringLiteral("view.jpg"));
        QVERIFY(!m_window->saveImageTo(jpeg, &error));
        QVERIFY2(error.startsWith(jpeg + QStringLiteral(": Save Image writes .png")), qPrintable(error));

        FullVolume volume(QString(), 64 * 1024);
        FACET_REQUIRE_FULL_VOLUME(volume);
        QVERIFY(volume.fill());
        const QString full = volume.filePath(QStringLiteral("view.png"));
        QVERIFY(!m_window->saveImageTo(full, &error));
        QVERIFY2(error.contains(full) && error.contains(QStringLiteral("No space left on device")),
            qPrintable(error));
        QCOMPARE(volume.entries(), QStringList {});
    }

    void stillAtAChosenSize_data()
    {
        QTest::addColumn<QString>("name");
        QTest::addColumn<QSize>("size");
        QTest::addColumn<bool>("transparent");
        QTest::newRow("PNG, larger than the view") << "big.png" << QSize(1300, 700) << false;
        QTest::newRow("PNG, transparent") << "clear.png" << QSize(320, 200) << true;
        QTest::newRow("EXR, odd size, transparent") << "clear.exr" << QSize(257, 129) << true;
        QTest::newRow("EXR, tall") << "tall.exr" << QSize(120, 400) << false;
    }

    void stillAtAChosenSize()
    {
        QFETCH(QString, name);
        QFETCH(QSize, size);
        QFETCH(bool, transparent);
        const QString path = m_dir.filePath(name);
        QString error;
        QVERIFY2(m_window->saveImageTo(path, &error, size, transparent), qPrintable(error));
        std::string problem;
        const std::optional<Image> image = Image::load(path.toStdString(), &problem);
        QVERIFY2(image, problem.c_str());
        QCOMPARE(QSize(image->width(), image->height()), size);
        // A corner is background (alpha 0 when transparent), the middle the sphere (opaque).
        QCOMPARE(image->at(0, 0).a, transparent ? 0.0f : 1.0f);
        QCOMPARE(image->at(size.width() / 2, size.height() / 2).a, 1.0f);
        QVERIFY(image->at(size.width() / 2, size.height() / 2).g > 0.01f);
    }

    void tooLargeAStillIsRefused()
    {
        const QString path = m_dir.filePath(QStringLiteral("huge.png"));
        QString error;
        QVERIFY(!m_window->saveImageTo(path, &error, QSize(9000, 64)));
        QVERIFY2(
            error.contains(QStringLiteral("9000x64 pixels is larger than the largest still, 8192 a side")),
            qPrintable(error));
        QVERIFY(!QFileInfo::exists(path));
    }

    void turntableFrames_data()
    {
        QTest::addColumn<QString>("name");
        QTest::addColumn<int>("subject");
        QTest::addColumn<int>("frames");
        QTest::newRow("object, PNG") << "object.png" << int(TurntableSubject::Object) << 3;
        QTest::newRow("environment, EXR") << "environment_##.exr" << int(TurntableSubject::Environment) << 3;
    }

    void turntableFrames()
    {
        QFETCH(QString, name);
        QFETCH(int, subject);
        QFETCH(int, frames);
        // A cube: a third of a turn shows another silhouette.
        ViewSettings view = m_window->document()->project().view;
        view.mesh = "cube";
        m_window->document()->setView(view, QStringLiteral("Mesh"));
        QTRY_VERIFY_WITH_TIMEOUT(m_window->sceneController()->pendingAssetLoads() == 0, 30000);
        const QString folder = m_dir.filePath(QStringLiteral("turntable-") + QString::number(subject));
        QVERIFY(QDir().mkpath(folder));
        const QString path = QDir(folder).filePath(name);
        SaveImageDialog::Choice choice;
        choice.size = QSize(96, 64);
        choice.frames = frames;
        choice.subject = TurntableSubject(subject);
        QString error;
        int asked = 0;
        QVERIFY2(m_window->imageSaver()->saveTurntableTo(path, choice, &error,
                     [&] {
                         ++asked;
                         return false;
                     }),
            qPrintable(error));
        QCOMPARE(asked, frames);
        QVERIFY2(m_window->statusMessage().startsWith(
                     QStringLiteral("Saved the turntable: %1 frames").arg(frames)),
            qPrintable(m_window->statusMessage()));
        QCOMPARE(QDir(folder).entryList(QDir::Files).size(), frames);
        std::vector<Image> images;
        for (int index = 0; index < frames; ++index) {
            std::string problem;
            std::optional<Image> image
                = Image::load(turntableFramePath(path.toStdString(), index, frames), &problem);
            QVERIFY2(image, problem.c_str());
            QCOMPARE(QSize(image->width(), image->height()), choice.size);
            images.push_back(std::move(*image));
        }
        float changed = 0.0f;
        for (int y = 0; y < 64; ++y)
            for (int x = 0; x < 96; ++x)
                changed = std::max(changed, glm::length(images[0].at(x, y) - images[1].at(x, y)));
        QVERIFY2(changed > 0.05f, qPrintable(QString::number(changed)));
        view.mesh = "sphere";
        m_window->document()->setView(view, QStringLiteral("Mesh"));
    }

    void turntableStopsWhenAsked()
    {
        const QString path = m_dir.filePath(QStringLiteral("stopped.png"));
        SaveImageDialog::Choice choice;
        choice.size = QSize(32, 32);
        choice.frames = 10;
        QString error;
        QVERIFY(!m_window->imageSaver()->saveTurntableTo(path, choice, &error, [] { return true; }));
        QCOMPARE(error, QStringLiteral("Turntable stopped after 1 of 10 frames (kept)"));
        QVERIFY(QFileInfo::exists(m_dir.filePath(QStringLiteral("stopped_0000.png"))));
        QVERIFY(!QFileInfo::exists(m_dir.filePath(QStringLiteral("stopped_0001.png"))));
    }

    void turntableVideo()
    {
        SaveImageDialog::Choice choice;
        choice.size = QSize(48, 32);
        choice.frames = 3;
        choice.format = SaveImageDialog::Format::Mp4;
        QString error;
        const QString missing = m_dir.filePath(QStringLiteral("missing.mp4"));
        qputenv("FACET_FFMPEG", m_dir.filePath(QStringLiteral("no-ffmpeg")).toLocal8Bit());
        QVERIFY(!m_window->imageSaver()->saveTurntableTo(missing, choice, &error));
        qunsetenv("FACET_FFMPEG");
        QVERIFY2(error.contains(
                     QStringLiteral("missing.mp4 needs ffmpeg, which is not installed (Debian: sudo apt "
                                    "install ffmpeg); or write the frames: choose PNG frames")),
            qPrintable(error));
        QVERIFY(!QFileInfo::exists(missing));
        // The dialog says so too, for a video format.
        qputenv("FACET_FFMPEG", m_dir.filePath(QStringLiteral("no-ffmpeg")).toLocal8Bit());
        SaveImageDialog dialog(SaveImageDialog::Kind::Turntable, QSize(64, 64), m_window.get());
        dialog.formatCombo()->setCurrentIndex(
            dialog.formatCombo()->findData(int(SaveImageDialog::Format::Mp4)));
        qunsetenv("FACET_FFMPEG");
        QVERIFY(dialog.findChild<QLabel*>(QStringLiteral("turntableFormatNote"))
                    ->text()
                    .startsWith(QStringLiteral("A video needs ffmpeg")));
        if (QStandardPaths::findExecutable(QStringLiteral("ffmpeg")).isEmpty())
            QSKIP("ffmpeg is not installed (Debian package ffmpeg): the video is not encoded here");
        const QString video = m_dir.filePath(QStringLiteral("turn.mp4"));
        QVERIFY2(m_window->imageSaver()->saveTurntableTo(video, choice, &error), qPrintable(error));
        QVERIFY(QFileInfo(video).size() > 0);
        QCOMPARE(m_window->statusMessage().left(22), QStringLiteral("Saved the turntable: ") + video.left(1));
    }

    void theDialogRemembersItsChoices()
    {
        const QSize viewSize(640, 480);
        {
            SaveImageDialog dialog(SaveImageDialog::Kind::Turntable, viewSize, m_window.get());
            QCOMPARE(dialog.widthSpin()->value(), 640); // the view's size at first
            dialog.widthSpin()->setValue(2048);
            dialog.heightSpin()->setValue(1024);
            dialog.transparentCheck()->setChecked(true);
            dialog.framesSpin()->setValue(72);
            dialog.subjectCombo()->setCurrentIndex(1);
            dialog.formatCombo()->setCurrentIndex(1);
            dialog.fpsSpin()->setValue(24);
            dialog.accept();
        }
        SaveImageDialog again(SaveImageDialog::Kind::Turntable, viewSize, m_window.get());
        const SaveImageDialog::Choice choice = again.choice();
        QCOMPARE(choice.size, QSize(2048, 1024));
        QVERIFY(choice.transparent);
        QCOMPARE(choice.frames, 72);
        QCOMPARE(choice.subject, TurntableSubject::Environment);
        QCOMPARE(choice.format, SaveImageDialog::Format::Exr);
        QCOMPARE(choice.fps, 24);
        QVERIFY(!again.fpsSpin()->isEnabled()); // frames have no frame rate
        // "View Size" takes the view's again; a view of another size starts from its own.
        again.findChild<QPushButton*>(QStringLiteral("saveImageViewSize"))->click();
        QCOMPARE(again.choice().size, viewSize);
        SaveImageDialog resized(SaveImageDialog::Kind::Still, QSize(800, 600), m_window.get());
        QCOMPARE(resized.choice().size, QSize(800, 600));
        QVERIFY(resized.framesSpin() == nullptr);
        QSettings().clear();
    }

    void compareGridIsPngOnly()
    {
        Project project = m_window->document()->project();
        project.compare.mode = CompareMode::Environments;
        m_window->document()->setProject(project, QStringLiteral("Compare"));
        QTRY_VERIFY_WITH_TIMEOUT(m_window->compareView()->isVisible(), 10000);
        QTest::qWait(1500);
        QString error;
        const QString exr = m_dir.filePath(QStringLiteral("grid.exr"));
        QVERIFY(!m_window->saveImageTo(exr, &error));
        QVERIFY2(error.contains(QStringLiteral("the compare grid saves as PNG")), qPrintable(error));
        QVERIFY(!QFileInfo::exists(exr));
        const QString png = m_dir.filePath(QStringLiteral("grid.png"));
        QVERIFY2(m_window->saveImageTo(png, &error), qPrintable(error));
        const QImage saved(png);
        QCOMPARE(
            saved.size(), m_window->compareView()->size() * m_window->compareView()->devicePixelRatioF());
    }

private:
    QTemporaryDir m_dir;
    std::unique_ptr<MainWindow> m_window;
};

QTEST_MAIN(SaveImageUiTest)
#include "SaveImageUiTest.moc"

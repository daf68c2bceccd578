// File > Save Image… (MainWindow::saveImageTo) as an artist uses it: the single view as a PNG
// (what it shows: the same display transform as the window's frame) and as a linear EXR (the scene
// radiance under it, HDR values a PNG cannot hold), each at the view's full size; the compare grid
// as shown (PNG; an EXR of it refused with why); a format it does not write and a full disk
// refused with the file named, nothing left behind.

#include <QAction>
#include <QDir>
#include <QTemporaryDir>
#include <QtTest/QTest>

#include <OpenImageIO/imageio.h>

#include <cmath>

#include "FullVolume.h"
#include "TestSupport.h"
#include "core/Image.h"
#include "ui/CompareView.h"
#include "ui/Document.h"
#include "ui/MainWindow.h"
#include "ui/SurfaceFormat.h"
#include "ui/ViewportWidget.h"

using namespace facet;
using facet::test::FullVolume;

class SaveImageUiTest : public QObject {
    Q_OBJECT
public:
    static void initMain()
    {
        FullVolume::isolateMounts();
        installViewportSurfaceFormat();
    }

private Q_SLOTS:
    void initTestCase()
    {
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

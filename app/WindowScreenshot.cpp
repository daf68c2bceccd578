#include "WindowScreenshot.h"

#include <QBuffer>
#include <QCoreApplication>
#include <QFileInfo>
#include <QImageWriter>
#include <QOpenGLWidget>
#include <QPixmap>
#include <QWidget>

#include <utility>

#include <cstdio>

#include "core/support/AtomicFile.h"
#include "ui/compare/CompareView.h"
#include "ui/viewport/SceneController.h"
#include "ui/viewport/ViewportWidget.h"

namespace facet {

WindowScreenshot::WindowScreenshot(
    QWidget* window, ViewportWidget* viewport, CompareView* compare, QString path, QObject* parent)
    : QObject(parent)
    , m_window(window)
    , m_path(std::move(path))
{
    // The grab goes after the first complete frame has reached the window, from the event loop,
    // so that the layout has settled and the viewport holds a finished picture. Previews drawn
    // while maps decode and upload (ViewportFrameStats::loadingMaps) are not it, nor frames
    // drawn while the lighting worker makes the environment's lighting (lightingPending), nor,
    // for a project lit by fis or reference, the frames before its refinement is done.
    connect(viewport, &QOpenGLWidget::frameSwapped, this, [this, viewport] {
        const ViewportFrameStats& frame = viewport->lastFrameStats();
        // The project's method, not the frame's: the full split-sum frame drawn before the
        // refinement starts (ViewportWidget::kRefineDelayMs) is not a refined one (it was taken for
        // one, so a fis project's screenshot showed the split sum).
        const SceneController* scene = viewport->sceneController();
        const bool refines = scene && scene->refinementMethod() != IblMethod::SplitSum;
        const bool refined = !refines || (frame.refineMethod != IblMethod::SplitSum && frame.refinement.done());
        if (!refined)
            m_timeout.start(kFirstFrameTimeoutMs); // progress: a refinement may take minutes
        if (!m_done && !frame.reduced && !frame.loadingMaps && frame.mapsHeldBack == 0 && refined
            && !frame.lightingPending && viewport->sceneController()
            && viewport->sceneController()->pendingAssetLoads() == 0) {
            if (refines)
                m_refinement = QStringLiteral(" (refined by %1, %2 samples)")
                                   .arg(QLatin1String(toString(frame.refineMethod)))
                                   .arg(frame.refinement.samples);
            QTimer::singleShot(0, this, &WindowScreenshot::save);
        }
    });
    // A project saved in a Compare mode opens in it, and the single viewport, hidden, draws
    // nothing: the compare view's first full frame with every environment loaded is the one
    // (in the error view, once its reference is done).
    if (compare)
        connect(compare, &QOpenGLWidget::frameSwapped, this, [this, compare] {
            const CompareFrameStats& frame = compare->lastFrameStats();
            if (compare->isRefining())
                m_timeout.start(kFirstFrameTimeoutMs); // progress, as the single view's refinement
            if (!m_done && compare->isVisible() && frame.frameNumber > 0 && !frame.reduced
                && !compare->isLoading() && !compare->isRefining())
                QTimer::singleShot(0, this, &WindowScreenshot::save);
        });
    m_timeout.setSingleShot(true);
    connect(&m_timeout, &QTimer::timeout, this, [this] {
        fail(QStringLiteral("the view drew no complete frame within %1 s").arg(kFirstFrameTimeoutMs / 1000));
    });
    m_timeout.start(kFirstFrameTimeoutMs);
}

bool WindowScreenshot::canWriteFormatOf(const QString& path, QString* why)
{
    const QString suffix = QFileInfo(path).suffix();
    if (QImageWriter::supportedImageFormats().contains(suffix.toLower().toLatin1()))
        return true;
    *why = suffix.isEmpty()
        ? QStringLiteral("the file name has no suffix (use .png)")
        : QStringLiteral("'.%1' is not an image format Qt can write (use .png)").arg(suffix);
    return false;
}

void WindowScreenshot::save()
{
    if (m_done)
        return;
    m_done = true;
    m_timeout.stop();

    QString why;
    if (!canWriteFormatOf(m_path, &why)) {
        fail(why);
        return;
    }
    const QByteArray format = QFileInfo(m_path).suffix().toLower().toLatin1();
    const QPixmap picture = m_window->grab();
    // Encoded in memory, then written through a checked temporary file and a rename
    // (core/support/AtomicFile.h): a failed save never leaves half a picture or harms an older one.
    QByteArray encoded;
    QBuffer buffer(&encoded);
    buffer.open(QIODevice::WriteOnly);
    if (!picture.save(&buffer, format.constData())) {
        fail(QStringLiteral("encoding the picture failed"));
        return;
    }
    std::string reason;
    if (!writeFileAtomically(m_path.toStdString(),
            std::string_view(encoded.constData(), std::size_t(encoded.size())), &reason)) {
        fail(QString::fromStdString(reason));
        return;
    }
    // The title says what the window showed (the project, or the asset it was made from).
    QString title = m_window->windowTitle();
    title.remove(QStringLiteral("[*]"));
    std::fprintf(stdout, "facet: saved %dx%d screenshot of \"%s\"%s to %s\n", picture.width(), picture.height(),
        qPrintable(title), qPrintable(m_refinement), qPrintable(m_path));
    std::fflush(stdout);
    QCoreApplication::exit(0);
}

void WindowScreenshot::fail(const QString& why)
{
    m_done = true;
    m_timeout.stop();
    std::fprintf(stderr, "facet: cannot save screenshot '%s': %s\n", qPrintable(m_path), qPrintable(why));
    QCoreApplication::exit(1);
}

} // namespace facet

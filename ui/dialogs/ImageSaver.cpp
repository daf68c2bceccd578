#include "ui/dialogs/ImageSaver.h"

#include "core/image/Image.h"
#include "core/image/VideoEncoder.h"
#include "core/support/AtomicFile.h"
#include "render/Turntable.h"
#include "ui/compare/CompareView.h"
#include "ui/document/Document.h"
#include "ui/viewport/ViewportWidget.h"

#include <QApplication>
#include <QBuffer>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QMessageBox>
#include <QProgressDialog>
#include <QSettings>

namespace facet {

namespace {
constexpr const char* kFolderKey = "saveImage/folder";
}

ImageSaver::ImageSaver(QWidget* window, Document* document, ViewportWidget* viewport,
    CompareView* compareView, std::function<bool()> gridShown)
    : QObject(window)
    , m_window(window)
    , m_document(document)
    , m_viewport(viewport)
    , m_compareView(compareView)
    , m_gridShown(std::move(gridShown))
{
}

bool ImageSaver::fail(const QString& why, QString* error)
{
    *error = why;
    Q_EMIT statusMessage(why);
    return false;
}

QString ImageSaver::chooseFile(const QString& title, const QString& filters, const QString& suffix)
{
    QString chosen;
    const QString path = QFileDialog::getSaveFileName(m_window, title,
        QDir(QSettings().value(QLatin1String(kFolderKey), QDir::homePath()).toString())
            .filePath(m_document->displayName() + QLatin1Char('.') + suffix),
        filters, &chosen);
    if (!path.isEmpty())
        QSettings().setValue(QLatin1String(kFolderKey), QFileInfo(path).absolutePath());
    return path;
}

void ImageSaver::saveImage()
{
    SaveImageDialog::Choice choice;
    const bool grid = m_gridShown();
    if (!grid) {
        SaveImageDialog dialog(SaveImageDialog::Kind::Still, m_viewport->deviceSize(), m_window);
        if (dialog.exec() != QDialog::Accepted)
            return;
        choice = dialog.choice();
    }
    QString filters = tr("PNG image, as shown (*.png)");
    if (!grid)
        filters += tr(";;OpenEXR, linear scene radiance (*.exr)");
    const QString path = chooseFile(tr("Save Image"), filters, QStringLiteral("png"));
    if (path.isEmpty())
        return;
    QString why;
    if (!saveImageTo(path, choice, &why))
        QMessageBox::warning(m_window, tr("Save Image"), why);
}

bool ImageSaver::saveImageTo(const QString& path, const SaveImageDialog::Choice& choice, QString* error)
{
    const QString suffix = QFileInfo(path).suffix().toLower();
    if (suffix != QStringLiteral("png") && suffix != QStringLiteral("exr"))
        return fail(tr("%1: Save Image writes .png (as shown) or .exr (linear radiance)").arg(path), error);
    QApplication::setOverrideCursor(Qt::WaitCursor);
    std::string problem;
    bool saved = false;
    if (m_gridShown()) {
        if (suffix == QStringLiteral("exr")) {
            QApplication::restoreOverrideCursor();
            return fail(
                tr("%1: the compare grid saves as PNG (its cells and labels as shown); a linear EXR is "
                   "of the single view")
                    .arg(path),
                error);
        }
        // The grid as shown: cells, labels, the error view's legend.
        QByteArray bytes;
        QBuffer buffer(&bytes);
        buffer.open(QIODevice::WriteOnly);
        saved = m_compareView->grab().toImage().save(&buffer, "PNG");
        if (!saved)
            problem = "cannot encode the grid as PNG";
        else if (!(saved = writeFileAtomically(path.toStdString(),
                       std::string_view(bytes.constData(), std::size_t(bytes.size())), &problem)))
            problem = "cannot write: " + problem;
    } else {
        // The single view drawn again offscreen: what it shows (PNG: the display transform) or the
        // scene radiance under it (EXR), converged to the project's samples.
        const FrameOutput output
            = suffix == QStringLiteral("exr") ? FrameOutput::LinearRadiance : FrameOutput::DisplayReferred;
        StillOptions options;
        options.transparent = choice.transparent;
        const std::optional<Image> image = m_viewport->renderStill(output, &problem, choice.size, options);
        saved = image && image->save(path.toStdString(), &problem, choice.transparent);
    }
    QApplication::restoreOverrideCursor();
    if (!saved)
        return fail(tr("Could not save the image: %1").arg(QString::fromStdString(problem)), error);
    Q_EMIT statusMessage(tr("Saved %1").arg(QDir::toNativeSeparators(path)));
    return true;
}

void ImageSaver::saveTurntable()
{
    if (m_gridShown()) {
        QMessageBox::information(m_window, tr("Save Turntable"),
            tr("A turntable is of the single view: leave the Compare mode (Compare > Single View) first."));
        return;
    }
    SaveImageDialog dialog(SaveImageDialog::Kind::Turntable, m_viewport->deviceSize(), m_window);
    if (dialog.exec() != QDialog::Accepted)
        return;
    const SaveImageDialog::Choice choice = dialog.choice();
    const QString path = chooseFile(tr("Save Turntable"), SaveImageDialog::filterFor(choice.format),
        SaveImageDialog::suffixFor(choice.format));
    if (path.isEmpty())
        return;
    QProgressDialog progress(tr("Rendering the turntable…"), tr("Stop"), 0, choice.frames, m_window);
    progress.setWindowModality(Qt::WindowModal);
    progress.setMinimumDuration(0);
    int shown = 0;
    QString why;
    const bool saved = saveTurntableTo(path, choice, &why, [&] {
        progress.setValue(++shown);
        progress.setLabelText(
            tr("Rendering frame %1 of %2…").arg(std::min(shown + 1, choice.frames)).arg(choice.frames));
        QCoreApplication::processEvents();
        return progress.wasCanceled();
    });
    progress.reset();
    if (!saved)
        QMessageBox::warning(m_window, tr("Save Turntable"), why);
}

bool ImageSaver::saveTurntableTo(const QString& path, const SaveImageDialog::Choice& choice, QString* error,
    const std::function<bool()>& cancelled)
{
    if (m_gridShown())
        return fail(tr("%1: a turntable is of the single view, not of the compare grid").arg(path), error);
    const QString suffix = QFileInfo(path).suffix().toLower();
    const bool video = isVideoPath(path.toStdString());
    if (!video && suffix != QStringLiteral("png") && suffix != QStringLiteral("exr"))
        return fail(tr("%1: a turntable is .png or .exr frames, or an .mp4 or .webm video").arg(path), error);
    if (video && findFfmpeg().empty()) {
        const QFileInfo file(path);
        return fail(QString::fromStdString(missingFfmpegAdvice(path.toStdString(),
                        tr("choose PNG frames (%1)")
                            .arg(file.dir().filePath(file.completeBaseName() + QStringLiteral("_0000.png")))
                            .toStdString())),
            error);
    }
    const FrameOutput output
        = suffix == QStringLiteral("exr") ? FrameOutput::LinearRadiance : FrameOutput::DisplayReferred;
    const bool transparent = choice.transparent && !video;
    std::string problem;
    const std::optional<TurntableWrite> written = writeTurntable(
        path.toStdString(), choice.frames, choice.fps, transparent,
        [&](int, double degrees, std::string* frameError) {
            StillOptions options;
            options.transparent = transparent;
            options.turntableSubject = choice.subject;
            options.turntableDegrees = degrees;
            return m_viewport->renderStill(output, frameError, choice.size, options);
        },
        &problem, cancelled);
    if (!written)
        return fail(tr("Could not save the turntable: %1").arg(QString::fromStdString(problem)), error);
    if (written->stopped) {
        const QString note = video ? tr("Turntable stopped after %1 of %2 frames; no video written")
                                   : tr("Turntable stopped after %1 of %2 frames (kept)");
        return fail(note.arg(written->framesWritten).arg(choice.frames), error);
    }
    const QString what = video ? QDir::toNativeSeparators(path)
                               : tr("%1 frames, %2 …")
                                     .arg(choice.frames)
                                     .arg(QDir::toNativeSeparators(QString::fromStdString(
                                         turntableFramePath(path.toStdString(), 0, choice.frames))));
    Q_EMIT statusMessage(tr("Saved the turntable: %1 (%2 s)")
                             .arg(what)
                             .arg(written->renderSeconds + written->encodeSeconds, 0, 'f', 1));
    return true;
}

} // namespace facet

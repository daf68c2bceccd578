#include "ui/viewport/ViewportDropHandler.h"

#include "core/project/AssetProject.h"
#include "ui/document/ProjectFileController.h"
#include "ui/widgets/DroppedFiles.h"

#include <QDragEnterEvent>
#include <QDropEvent>
#include <QFileInfo>
#include <QMimeData>
#include <QTimer>
#include <QUrl>
#include <QWidget>

namespace facet {

namespace {

bool isProjectFileName(const QString& path)
{
    return QFileInfo(path).suffix().compare(QLatin1String("json"), Qt::CaseInsensitive) == 0;
}

} // namespace

ViewportDropHandler::ViewportDropHandler(ProjectFileController* files, QWidget* viewport, QObject* parent)
    : QObject(parent)
    , m_files(files)
    , m_viewport(viewport)
{
    m_viewport->setAcceptDrops(true);
    m_viewport->installEventFilter(this);
}

QString ViewportDropHandler::usableFile(const QStringList& paths)
{
    for (const QString& path : paths)
        if (isAssetFileName(path.toStdString()) && !QFileInfo(path).isDir())
            return path;
    for (const QString& path : paths)
        if (isProjectFileName(path) && !QFileInfo(path).isDir())
            return path;
    return {};
}

bool ViewportDropHandler::dropFiles(const QStringList& paths)
{
    const QString file = usableFile(paths);
    if (file.isEmpty())
        return false;
    return isAssetFileName(file.toStdString()) ? m_files->importAssetFile(file) : m_files->openFile(file);
}

bool ViewportDropHandler::eventFilter(QObject* watched, QEvent* event)
{
    if (watched != m_viewport)
        return false;
    switch (event->type()) {
    case QEvent::DragEnter:
    case QEvent::DragMove: {
        auto* drag = static_cast<QDragMoveEvent*>(event);
        if (!usableFile(droppedLocalFiles(drag->mimeData())).isEmpty())
            drag->acceptProposedAction();
        else
            drag->ignore();
        return true;
    }
    case QEvent::Drop: {
        auto* drop = static_cast<QDropEvent*>(event);
        const QStringList files = droppedLocalFiles(drop->mimeData());
        if (usableFile(files).isEmpty()) {
            drop->ignore();
            return true;
        }
        drop->acceptProposedAction();
        // After the drop has returned to the source: opening may ask about unsaved changes
        // (a modal box), which must not run inside the drag-and-drop's own event.
        QTimer::singleShot(0, this, [this, files] { dropFiles(files); });
        return true;
    }
    default:
        return false;
    }
}

} // namespace facet

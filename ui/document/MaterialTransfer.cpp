#include "ui/document/MaterialTransfer.h"

#include "core/material/MaterialList.h"
#include "core/project/Project.h"
#include "ui/document/Document.h"
#include "ui/viewport/PartPicker.h"
#include "ui/viewport/SceneController.h"

#include <QApplication>
#include <QDrag>
#include <QDragMoveEvent>
#include <QDropEvent>
#include <QJsonDocument>
#include <QJsonObject>
#include <QListWidget>
#include <QMimeData>
#include <QMouseEvent>

namespace facet {

QMimeData* materialMimeData(const Material& material, std::optional<int> projectIndex)
{
    const QByteArray json
        = QJsonDocument(materialToJson(material, std::string())).toJson(QJsonDocument::Compact);
    auto* mime = new QMimeData;
    mime->setData(QLatin1String(kMaterialMime), json);
    mime->setText(QString::fromUtf8(json));
    if (projectIndex)
        mime->setData(QLatin1String(kMaterialIndexMime), QByteArray::number(*projectIndex));
    return mime;
}

std::optional<TransferredMaterial> materialFromMimeData(const QMimeData* mime, std::string* error)
{
    QByteArray json = mime ? mime->data(QLatin1String(kMaterialMime)) : QByteArray();
    if (json.isEmpty() && mime && mime->hasText())
        json = mime->text().toUtf8();
    const QJsonDocument document = QJsonDocument::fromJson(json);
    std::string problem;
    const std::optional<Material> material = document.isObject()
        ? materialFromJson(document.object(), std::string(), "material", &problem)
        : std::nullopt;
    if (error)
        *error = problem;
    if (!material)
        return std::nullopt;
    TransferredMaterial transferred {*material, std::nullopt};
    bool ok = false;
    const int index = mime->data(QLatin1String(kMaterialIndexMime)).toInt(&ok);
    if (ok)
        transferred.projectIndex = index;
    return transferred;
}

namespace {

// Starts a drag of a list's item once the mouse has moved far enough with the left button down.
class DragSource : public QObject {
public:
    DragSource(QListWidget* list, std::function<QMimeData*(const QListWidgetItem*)> mime)
        : QObject(list)
        , m_list(list)
        , m_mime(std::move(mime))
    {
        list->viewport()->installEventFilter(this);
    }

protected:
    bool eventFilter(QObject*, QEvent* event) override
    {
        if (event->type() == QEvent::MouseButtonPress) {
            const auto* mouse = static_cast<QMouseEvent*>(event);
            m_pressedAt = mouse->button() == Qt::LeftButton ? std::optional(mouse->position()) : std::nullopt;
        } else if (event->type() == QEvent::MouseButtonRelease) {
            m_pressedAt.reset();
        } else if (event->type() == QEvent::MouseMove && m_pressedAt) {
            const auto* mouse = static_cast<QMouseEvent*>(event);
            if ((mouse->position() - *m_pressedAt).manhattanLength() < QApplication::startDragDistance())
                return false;
            const QListWidgetItem* item = m_list->itemAt(m_pressedAt->toPoint());
            m_pressedAt.reset();
            QMimeData* data = item ? m_mime(item) : nullptr;
            if (!data)
                return false;
            auto* drag = new QDrag(m_list);
            drag->setMimeData(data);
            if (!item->icon().isNull())
                drag->setPixmap(item->icon().pixmap(48, 48));
            drag->exec(Qt::CopyAction);
            return true;
        }
        return false;
    }

private:
    QListWidget* m_list;
    std::function<QMimeData*(const QListWidgetItem*)> m_mime;
    std::optional<QPointF> m_pressedAt;
};

bool carriesMaterial(const QMimeData* mime)
{
    return mime && mime->hasFormat(QLatin1String(kMaterialMime));
}

} // namespace

void makeMaterialDragSource(QListWidget* list, std::function<QMimeData*(const QListWidgetItem*)> mime)
{
    new DragSource(list, std::move(mime));
}

MaterialDropHandler::MaterialDropHandler(
    Document* document, PartPicker* picker, QWidget* viewport, QObject* parent)
    : QObject(parent)
    , m_document(document)
    , m_picker(picker)
    , m_viewport(viewport)
{
    m_viewport->setAcceptDrops(true);
    m_viewport->installEventFilter(this);
}

bool MaterialDropHandler::dropMaterial(const QMimeData* mime, const QPointF& position)
{
    std::string error;
    const std::optional<TransferredMaterial> dropped = materialFromMimeData(mime, &error);
    if (!dropped) {
        Q_EMIT message(tr("The dropped material cannot be used: %1").arg(QString::fromStdString(error)));
        return false;
    }
    const std::optional<int> part = m_picker->partAt(position);
    const QString name = QString::fromStdString(dropped->material.name);
    if (!part) {
        Q_EMIT message(tr("Drop “%1” on a part of the mesh to give it that material").arg(name));
        return false;
    }
    Project project = m_document->project();
    // Every part up to the dropped one gets its entry (a part without one shows material 0).
    if (project.parts.size() <= std::size_t(*part))
        project.parts.resize(std::size_t(*part) + 1);
    const QString partName = m_picker->partName(*part);
    // The index names a material of this project only if it still is that material (a drag from
    // another window carries its own project's index).
    int material = dropped->projectIndex.value_or(-1);
    if (material < 0 || std::size_t(material) >= project.materials.size()
        || !(project.materials[std::size_t(material)] == dropped->material))
        material = -1;
    QString undoText;
    if (material >= 0) {
        if (project.parts[std::size_t(*part)].material == material) {
            Q_EMIT message(tr("%1 already shows “%2”").arg(partName, name));
            return false;
        }
        undoText = tr("Assign %1 to %2").arg(name, partName);
    } else {
        std::string problem;
        const int index = int(project.materials.size());
        std::optional<Project> added = withMaterialInserted(project, index, dropped->material, &problem);
        if (!added) {
            Q_EMIT message(tr("Could not add “%1”: %2").arg(name, QString::fromStdString(problem)));
            return false;
        }
        project = std::move(*added);
        material = index;
        undoText = tr("Drop %1 onto %2")
                       .arg(QString::fromStdString(project.materials[std::size_t(index)].name), partName);
    }
    project.parts[std::size_t(*part)].material = material;
    project.currentMaterial = material;
    m_document->setProject(project, undoText);
    Q_EMIT message(tr("%1 shows “%2”")
                       .arg(partName, QString::fromStdString(project.materials[std::size_t(material)].name)));
    return true;
}

bool MaterialDropHandler::eventFilter(QObject* watched, QEvent* event)
{
    if (watched != m_viewport)
        return false;
    switch (event->type()) {
    case QEvent::DragEnter:
    case QEvent::DragMove: {
        auto* drag = static_cast<QDragMoveEvent*>(event);
        if (!carriesMaterial(drag->mimeData()))
            return false; // files: the file-drop handler's
        // Moves are accepted only over a part: the cursor says where a drop would land. (The
        // enter is accepted anywhere, or no move would follow.)
        if (event->type() == QEvent::DragEnter || m_picker->partAt(drag->position()))
            drag->acceptProposedAction();
        else
            drag->ignore();
        return true;
    }
    case QEvent::Drop: {
        auto* drop = static_cast<QDropEvent*>(event);
        if (!carriesMaterial(drop->mimeData()))
            return false;
        if (dropMaterial(drop->mimeData(), drop->position()))
            drop->acceptProposedAction();
        else
            drop->ignore();
        return true;
    }
    default:
        return false;
    }
}

} // namespace facet

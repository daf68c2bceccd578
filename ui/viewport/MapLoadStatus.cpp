#include "ui/viewport/MapLoadStatus.h"

#include "ui/viewport/SceneController.h"

namespace facet {

MapLoadStatus::MapLoadStatus(SceneController* scene, QWidget* parent)
    : QLabel(parent)
{
    setObjectName(QStringLiteral("mapLoadStatus"));
    hide();
    connect(scene, &SceneController::mapLoadProgress, this, &MapLoadStatus::onProgress);
}

void MapLoadStatus::onProgress(int loaded, int total, double milliseconds)
{
    if (total <= 0 || loaded >= total) {
        setToolTip(total > 0
                ? tr("%n texture map(s) loaded in %1 ms", nullptr, total).arg(milliseconds, 0, 'f', 0)
                : QString());
        clear();
        hide();
        return;
    }
    setText(tr("Loading maps %1 of %2…").arg(loaded + 1).arg(total));
    show();
}

} // namespace facet

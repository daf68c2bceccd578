#pragma once
// The status bar's map-loading progress: "Loading maps 2 of 5…" while SceneController decodes a
// texture set off the GUI thread, hidden when no map is loading. A permanent status-bar widget,
// so that it never replaces a message (an error about a map stays readable beside it).

#include <QLabel>

namespace facet {

class SceneController;

class MapLoadStatus : public QLabel {
    Q_OBJECT
public:
    explicit MapLoadStatus(SceneController* scene, QWidget* parent = nullptr);

private:
    void onProgress(int loaded, int total, double milliseconds);
};

} // namespace facet

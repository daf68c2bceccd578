#pragma once
// Files dropped on the viewport (an event filter; the viewport widget itself knows nothing about
// files): a glTF asset (.gltf, .glb) is imported into the current project, as File > Import Asset
// does (one undo step: its mesh, materials and parts replace the project's); a Facet project
// (.json) is opened, as File > Open does. Only drags that carry one of those are accepted, so the
// cursor says at once whether a drop will do something; texture maps go on the Texture Maps dock.

#include <QObject>
#include <QString>
#include <QStringList>

class QWidget;

namespace facet {

class ProjectFileController;

class ViewportDropHandler : public QObject {
    Q_OBJECT
public:
    ViewportDropHandler(ProjectFileController* files, QWidget* viewport, QObject* parent = nullptr);

    // The file of `paths` a drop would use: the first glTF asset, else the first project; empty
    // when there is none.
    static QString usableFile(const QStringList& paths);
    // What a drop of `paths` does (tests call it; a drop event comes here). False when nothing
    // was usable or the import / open failed (the controller reported why).
    bool dropFiles(const QStringList& paths);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    ProjectFileController* m_files;
    QWidget* m_viewport;
};

} // namespace facet

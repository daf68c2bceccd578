#pragma once
// The Environment library dock: thumbnails of the built-in environments (studio, sky), of the
// installed CC0 samples' HDRIs (AssetLibrary::installed(), hdri/) and of the user's libraries
// (folders added with Add Folder…, each named once: core/project/AssetLibrary.h), so that projects refer
// to them by library name. Labels say where each comes from ("Studio (built-in)", "Studio (CC0
// sample)", "Loft (my-hdris)"), tooltips give the file and how projects store it. Thumbnails are
// made off the GUI thread (ThumbnailLoader). Choosing one relights the viewport (one undo step);
// Ctrl- or Shift-clicking selects several without relighting, for Compare > Compare Selected
// Environments (ui/compare/CompareActions.h), which reads selectedSources().
// Below: rotation, intensity in EV (stored as the linear intensity 2^EV), the background
// (environment, blurred by a roughness, or a solid colour) and the IBL quality preset; a busy bar
// and the lighting's status (ui/widgets/WindowMessages.h).

#include "ui/document/DocumentChanges.h"

#include <QDockWidget>

class QComboBox;
class QLabel;
class QListWidget;
class QListWidgetItem;
class QProgressBar;

namespace facet {

class ColorButton;
class Document;
class ThumbnailLoader;
class ValueSlider;

class EnvironmentDock : public QDockWidget {
    Q_OBJECT
public:
    static constexpr int kThumbnailWidth = 128;
    static constexpr double kMinEV = -8.0; // intensity 2^-8; 0 is below the slider, typed as -8

    explicit EnvironmentDock(Document* document, QWidget* parent = nullptr);
    ~EnvironmentDock() override;

    QListWidget* library() const { return m_library; }
    // The folder of the installed CC0 HDRIs.
    static QString installedHdriFolder();
    // The label and tooltip of an entry for `source` (an environment spec or absolute path).
    static QString entryLabel(const QString& source);
    static QString entryToolTip(const QString& source);
    // Adds a folder of .exr/.hdr images to the library as a user library (AssetLibrary::
    // addUserLibrary names it). False with a message when it holds none.
    bool addFolder(const QString& folder);
    // Selects the library entry of `source` (an environment spec) and sets it on the document.
    bool chooseEnvironment(const QString& source);
    // The sources of the selected entries in the order they were selected (a Shift range in
    // the list's order).
    QStringList selectedSources() const;
    // Thumbnail jobs still running, and the time the finished ones took in all (ms).
    int pendingThumbnails() const;
    double thumbnailMilliseconds() const { return m_thumbnailMs; }

public Q_SLOTS:
    // The lighting's status (ui/widgets/WindowMessages.h wording), with the busy bar while it is computed.
    void showLightingStatus(const QString& text, bool busy);
    // The lighting being computed, `fraction` (0..1) done: the bar shows how far.
    void showLightingProgress(const QString& text, double fraction);

Q_SIGNALS:
    void message(const QString& text);
    // The library's selection changed; `count` entries are selected.
    void selectionChanged(int count);

private:
    void rebuildLibrary();
    QListWidgetItem* addEntry(const QString& source);
    void onDocumentChanged(DocumentChanges changes);
    void onItemActivated(QListWidgetItem* item);
    void onSelectionChanged();

    Document* m_document;
    ThumbnailLoader* m_thumbnails;
    QListWidget* m_library;
    ValueSlider* m_rotation;
    ValueSlider* m_exposure;
    QComboBox* m_background;
    ValueSlider* m_blur;
    ColorButton* m_backgroundColor;
    QComboBox* m_quality;
    QComboBox* m_method; // environment.method: what the still view refines to
    QLabel* m_status; // objectName "environmentStatus"
    QProgressBar* m_busy;
    double m_thumbnailMs = 0.0;
    QStringList m_selectionOrder; // sources, oldest selection first
};

} // namespace facet

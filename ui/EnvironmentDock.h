#pragma once
// The Environment library dock: thumbnails of the built-in environments (studio, sky), of the
// CC0 HDRIs the setup installs ($FACET_ASSETS_DIR/hdri, else ~/.local/share/facet/assets/hdri)
// and of folders the user adds (remembered in QSettings). Thumbnails are made off the GUI
// thread (ThumbnailLoader). Choosing one relights the viewport (one undo step). Below: rotation,
// intensity in EV (stored as the linear intensity 2^EV), the background (environment, blurred by
// a roughness, or a solid colour) and the IBL quality preset; a busy bar while an environment's
// lighting is computed.

#include "ui/DocumentChanges.h"

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
    // Adds a folder of .exr/.hdr images to the library (and to QSettings). False with a message
    // when it holds none.
    bool addFolder(const QString& folder);
    // Selects the library entry of `source` (an environment spec) and sets it on the document.
    bool chooseEnvironment(const QString& source);
    // Thumbnail jobs still running, and the time the finished ones took in all (ms).
    int pendingThumbnails() const;
    double thumbnailMilliseconds() const { return m_thumbnailMs; }

public Q_SLOTS:
    // From the viewport: the lighting of `name` is being computed / is ready.
    void showPrecomputeStarting(const QString& name);
    void showPrecomputeFinished(const QString& name, double milliseconds);

Q_SIGNALS:
    void message(const QString& text);

private:
    void rebuildLibrary();
    QListWidgetItem* addEntry(const QString& source, const QString& label);
    void onDocumentChanged(DocumentChanges changes);
    void onItemActivated(QListWidgetItem* item);

    Document* m_document;
    ThumbnailLoader* m_thumbnails;
    QListWidget* m_library;
    ValueSlider* m_rotation;
    ValueSlider* m_exposure;
    QComboBox* m_background;
    ValueSlider* m_blur;
    ColorButton* m_backgroundColor;
    QComboBox* m_quality;
    QLabel* m_status;
    QProgressBar* m_busy;
    double m_thumbnailMs = 0.0;
};

} // namespace facet
